package rtd.window;

import java.util.List;

/**
 * The passes of one render, as the sides of their blocks: a new scene or camera starts coarse and is refined
 * ({@link #STILL}: 8, 4, 2, 1 pixels); while the camera moves, each frame renders at the moving resolution alone
 * ({@link #MOVING}: a quarter of the pixels); once the mouse rests, the full picture follows ({@link #RESTED}).
 *
 * @param blocks the sides of the blocks, coarsest first
 */
record Refinement(List<Integer> blocks) {

    static final Refinement STILL = new Refinement(List.of(8, 4, 2, 1));
    static final Refinement MOVING = new Refinement(List.of(2));
    static final Refinement RESTED = new Refinement(List.of(1));

    Refinement {
        blocks = List.copyOf(blocks);
    }

    /** Whether the last pass is the full picture. */
    boolean endsFull() {
        return blocks.get(blocks.size() - 1) == 1;
    }
}
