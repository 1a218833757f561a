package rtd.accel;

import java.util.Arrays;
import java.util.List;
import rtd.geometry.IGeometry;

/**
 * The first step of building a {@link Bvh}: each object's box measured once, in file order, into
 * the arrays the builder sorts, and the objects whose box is not finite (planes) set apart behind
 * the others, which the tree holds.
 */
final class ObjectBoxes {

    private final List<IGeometry> objects;
    private final ObjectArrays into;
    /** Whether {@link #measure} met an object without a finite box. */
    private boolean anyUnbounded;

    private ObjectBoxes(List<IGeometry> objects, ObjectArrays into) {
        this.objects = objects;
        this.into = into;
    }

    /**
     * Measures each of {@code objects} into {@code into} (its place {@code i}: box and order);
     * then moves the objects without a finite box behind the others, each group in file order. Answers their places in the file, in file order; the others are places
     * {@code [0, objects.size() − answer.length)} of {@code into}.
     */
    static int[] measure(List<IGeometry> objects, ObjectArrays into) {
        ObjectBoxes boxes = new ObjectBoxes(objects, into);
        for (int i = 0; i < objects.size(); i++) {
            boxes.measure(i);
        }
        return boxes.anyUnbounded ? boxes.setUnboundedApart() : new int[0];
    }

    /** Puts object {@code i}'s box in place {@code i}. */
    private void measure(int i) {
        KnownShapes.putBox(objects.get(i), into.boxes(), 6 * i);
        into.order()[i] = i;
        if (!isFinite(i)) {
            anyUnbounded = true;
        }
    }

    private int[] setUnboundedApart() {
        int kept = 0;
        int[] apart = new int[0];
        for (int i = 0; i < objects.size(); i++) {
            if (isFinite(i)) {
                if (kept != i) {
                    into.order()[kept] = into.order()[i];
                    System.arraycopy(into.boxes(), 6 * i, into.boxes(), 6 * kept, 6);
                }
                kept++;
            } else {
                apart = Arrays.copyOf(apart, apart.length + 1);
                apart[apart.length - 1] = into.order()[i];
            }
        }
        System.arraycopy(apart, 0, into.order(), kept, apart.length);
        return apart;
    }

    private boolean isFinite(int i) {
        for (int k = 0; k < 6; k++) {
            if (!Float.isFinite(into.boxes()[6 * i + k])) {
                return false;
            }
        }
        return true;
    }
}
