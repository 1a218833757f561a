package rtd.accel;

/**
 * The objects a {@link BvhBuilder} sorts into its tree: per place, the object's place in the
 * scene file ({@code order}) and its box ({@code boxes[6i .. 6i+5]}: min x, y, z, max x, y, z).
 * The builder keeps two sets and partitions a node's objects from one into the other
 * ({@link #scatter}): each object is copied once per level, read front to back, with no swaps.
 *
 * @param order places in the scene file
 * @param boxes six floats per place
 */
record ObjectArrays(int[] order, float[] boxes) {

    /** Two arrays for {@code count} objects. */
    static ObjectArrays of(int count) {
        return new ObjectArrays(new int[count], new float[6 * count]);
    }

    /** Copies the objects of places {@code [start, end)} to the same places of {@code to}. */
    void copy(int start, int end, ObjectArrays to) {
        System.arraycopy(order, start, to.order, start, end - start);
        System.arraycopy(boxes, 6 * start, to.boxes, 6 * start, 6 * (end - start));
    }

    /**
     * Copies the objects of places {@code [start, end)} to {@code to}, keeping their order:
     * those whose centre along {@code axis} lies in a bin {@code ≤ lastLeftBin}
     * ({@link SahBins#binOf}) to the places from {@code left} on, the others from {@code right}
     * on. Without a branch on the side: which side an object goes to is as good as random, and
     * a mispredicted branch per object cost more than the copy.
     */
    void scatter(int start, int end, int axis, float lo, float scale, int lastLeftBin, ObjectArrays to,
            int left, int right) {
        int[] toOrder = to.order;
        float[] toBoxes = to.boxes;
        for (int i = start; i < end; i++) {
            int at = 6 * i;
            int bin = SahBins.binOf((boxes[at + axis] + boxes[at + axis + 3]) * 0.5f, lo, scale);
            int goesRight = (lastLeftBin - bin) >>> 31; // 1 if bin > lastLeftBin (the difference's sign bit), else 0
            int place = left + ((right - left) & -goesRight); // right if it goes right (-1 masks all bits), else left
            left += 1 - goesRight;
            right += goesRight;
            toOrder[place] = order[i];
            int to6 = 6 * place;
            toBoxes[to6] = boxes[at];
            toBoxes[to6 + 1] = boxes[at + 1];
            toBoxes[to6 + 2] = boxes[at + 2];
            toBoxes[to6 + 3] = boxes[at + 3];
            toBoxes[to6 + 4] = boxes[at + 4];
            toBoxes[to6 + 5] = boxes[at + 5];
        }
    }
}
