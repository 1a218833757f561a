package rtd.accel;

import java.util.concurrent.ForkJoinPool;

import rtd.geometry.IGeometry;
import rtd.scene.Color;
import rtd.scene.Scene;

/**
 * A bounding volume hierarchy: a binary tree of boxes over the scene's objects, so that a ray
 * tests only the objects whose boxes it passes through, about log N instead of the N of
 * Listing 4.3. It is not in the paper; it is the usual way to make ray tracing fast.
 *
 * <p>The tree is stored flat, for speed: node {@code i} has its box in
 * {@code bounds[6i .. 6i+5]} (min x, y, z, max x, y, z) and two numbers in
 * {@code nodes[2i], nodes[2i+1]}. An inner node has {@code nodes[2i+1] == INNER} and its
 * children at {@code nodes[2i]} and {@code nodes[2i] + 1}; a leaf holds {@code nodes[2i+1]}
 * objects starting at {@code objects[nodes[2i]]}. The objects are sorted so that each leaf's are
 * adjacent; {@code fileOrder} keeps each one's place in the scene file for the depth test's
 * tie rule.
 */
public final class Bvh {

    /** Marks an inner node in {@code nodes[2i+1]}, where a leaf has its object count. */
    static final int INNER = -1;

    final float[] bounds;
    final int[] nodes;
    final IGeometry[] objects;
    /** Each object's colour as {@code 0xRRGGBB}, in the order of {@code objects}. */
    final int[] colours;
    /** Each object's box ({@link IGeometry#bounds}), in the order of {@code objects}, 6 floats each. */
    final float[] objectBounds;
    final int[] fileOrder;
    /** The objects packed for fast tests when they are all spheres, else {@code null}. */
    final PackedSpheres spheres;
    final int maxDepth;
    final Color ambient;

    Bvh(float[] bounds, int[] nodes, IGeometry[] objects, int[] colours, float[] objectBounds, PackedSpheres spheres, int[] fileOrder,
            int maxDepth, Color ambient) {
        this.bounds = bounds;
        this.nodes = nodes;
        this.objects = objects;
        this.colours = colours;
        this.objectBounds = objectBounds;
        this.fileOrder = fileOrder;
        this.spheres = spheres;
        this.maxDepth = maxDepth;
        this.ambient = ambient;
    }

    /**
     * Builds the hierarchy for {@code scene} with all cores. It depends on the camera because
     * each object's box also holds the hits that rounding adds, which grow with the distance
     * from the ray origins (see {@link IGeometry#bounds}).
     */
    public static Bvh build(Scene scene) {
        return build(scene, Runtime.getRuntime().availableProcessors());
    }

    /**
     * Builds the hierarchy for {@code scene} with {@code threads} threads; the tree is the same
     * for any number. A small scene is built on the calling thread: starting threads would take
     * longer than building it.
     */
    public static Bvh build(Scene scene, int threads) {
        if (threads == 1 || scene.objects().size() < BvhBuilder.PARALLEL_THRESHOLD) {
            return new BvhBuilder(scene.objects(), scene.camera(), null).build(scene.ambient());
        }
        ForkJoinPool pool = new ForkJoinPool(threads);
        try {
            return new BvhBuilder(scene.objects(), scene.camera(), pool).build(scene.ambient());
        } finally {
            pool.shutdown();
        }
    }

    /** A new tracer that follows rays through this hierarchy; one per thread. */
    public BvhTracer newTracer() {
        return new BvhTracer(this);
    }

    /** The number of nodes in the tree. */
    public int nodeCount() {
        return nodes.length / 2;
    }
}
