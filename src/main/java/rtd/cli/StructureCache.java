package rtd.cli;

import java.util.List;
import java.util.function.Supplier;
import rtd.accel.Bvh;
import rtd.accel.LightGrids;
import rtd.scene.Scene;

/**
 * The structures of a run's frames that do not depend on the camera, kept from one frame to the next: the BVH
 * while the frame's objects equal the last frame's, the light grids while its objects and lights do. Records
 * compare by value; a shape that is no record (a mesh's triangle) equals only itself, so a shape made anew is
 * built anew. A camera that moves over still objects rebuilds only the view grid, and every pixel is the one a
 * build from nothing gives.
 */
final class StructureCache {

    private final Last<List<?>, Bvh> bvh = new Last<>();
    private final Last<List<?>, LightGrids> lightGrids = new Last<>();

    /** The BVH of {@code scene}'s objects: the last one if they are equal to its objects. */
    Bvh bvh(Scene scene) {
        return bvh.get(scene.objects(), () -> Bvh.build(scene));
    }

    /** The light grids of {@code scene}'s objects and lights: the last ones if both, and the size, are equal. */
    LightGrids lightGrids(Scene scene, int width, int height, int samples, int threads) {
        return lightGrids.get(List.of(scene.objects(), scene.lights(), width, height, samples),
                () -> LightGrids.build(scene, width, height, samples, threads));
    }

    /** The last value built and what it was built for; its own lock, so that two structures build side by side. */
    private static final class Last<K, V> {
        private K key;
        private V value;

        synchronized V get(K wanted, Supplier<V> build) {
            if (value == null || !wanted.equals(key)) {
                key = null;
                value = null; // the old structure and its objects may go before the new one is built
                value = build.get();
                key = wanted;
            }
            return value;
        }
    }
}
