package rtd.window;

import java.util.List;

/**
 * The passes of one render, as the sides of their blocks: a new scene or camera starts coarse and is refined
 * ({@link #STILL}: 8, 4, 2, 1 pixels); while the camera moves, each frame renders at the moving resolution alone
 * ({@link #MOVING}: a quarter of the pixels, coarser for a scene too slow for that: {@link #moving}); once the mouse
 * rests, the full picture follows ({@link #RESTED}).
 *
 * @param blocks the sides of the blocks, coarsest first
 */
record Refinement(List<Integer> blocks) {

    /** The time a moving frame may take: 15 frames per second, smooth enough to follow the mouse. */
    static final long FRAME_NANOS = 1_000_000_000L / 15;
    /** The coarsest blocks a moving frame takes when blocks of 2 would be too slow. */
    static final int COARSEST_MOVING = 8;

    static final Refinement STILL = new Refinement(List.of(8, 4, 2, 1));
    static final Refinement MOVING = new Refinement(List.of(2));
    static final Refinement RESTED = new Refinement(List.of(1));

    Refinement {
        blocks = List.copyOf(blocks);
    }

    /**
     * The moving frame after one of blocks of {@code block} pixels that took {@code nanos}: blocks of 2 (a quarter of
     * the pixels, the moving resolution) if their rays would fit in {@link #FRAME_NANOS}, else blocks of 4 if theirs
     * would, else 8; so a heavy scene still follows the mouse. Before any moving frame ({@code nanos} 0), blocks of 2.
     */
    static Refinement moving(int block, long nanos) {
        int next = 2;
        while (next < COARSEST_MOVING && nanos * ((double) block * block) / (next * next) > FRAME_NANOS) {
            next *= 2; // a quarter of the rays, about a quarter of the time
        }
        return next == 2 ? MOVING : new Refinement(List.of(next));
    }

    /** Whether the last pass is the full picture. */
    boolean endsFull() {
        return blocks.get(blocks.size() - 1) == 1;
    }
}
