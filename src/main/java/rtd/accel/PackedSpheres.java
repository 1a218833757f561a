package rtd.accel;

import java.util.Arrays;
import java.util.stream.IntStream;

import rtd.geometry.IGeometry;
import rtd.geometry.Sphere;

/**
 * The scene's spheres side by side in one array, in the order of the {@link Bvh}'s leaves, so
 * that the spheres of a leaf lie next to each other in memory: centre x, y, z and r² of sphere
 * {@code i} at {@code [4i .. 4i+3]}.
 *
 * <p>{@link #hit} is {@link Sphere#intersect} (equations 3.6 to 3.8) on these numbers, with
 * the same float operations in the same order, so it finds the same {@code t} to the last
 * bit; it only skips making objects. With a million spheres this matters: following a
 * reference to each sphere and to its centre is a wait for memory per test, while the
 * spheres of a leaf here arrive together.
 */
final class PackedSpheres {

    private final float[] spheres;

    private PackedSpheres(float[] spheres) {
        this.spheres = spheres;
    }

    /**
     * The objects packed, or {@code null} if any of them is not a sphere; in {@code parallel}
     * on the pool it is called from, or on the calling thread alone.
     */
    static PackedSpheres packOrNull(IGeometry[] objects, boolean parallel) {
        float[] spheres = new float[4 * objects.length];
        if (!parallel) {
            for (int i = 0; i < objects.length; i++) {
                if (!(objects[i] instanceof Sphere)) {
                    return null;
                }
                pack(objects, i, spheres);
            }
            return new PackedSpheres(spheres);
        }
        if (!Arrays.stream(objects).parallel().allMatch(object -> object instanceof Sphere)) {
            return null;
        }
        IntStream.range(0, objects.length).parallel().forEach(i -> pack(objects, i, spheres));
        return new PackedSpheres(spheres);
    }

    private static void pack(IGeometry[] objects, int i, float[] spheres) {
        Sphere sphere = (Sphere) objects[i];
        spheres[4 * i] = sphere.center().x();
        spheres[4 * i + 1] = sphere.center().y();
        spheres[4 * i + 2] = sphere.center().z();
        spheres[4 * i + 3] = sphere.radius() * sphere.radius();
    }

    /**
     * The smallest {@code t ≥ 0} where the ray O + t·D hits sphere {@code i}, or NaN;
     * {@code dd} is D·D, the same for every sphere.
     */
    float hit(int i, float ox, float oy, float oz, float dx, float dy, float dz, float dd) {
        int at = 4 * i;
        float mx = ox - spheres[at];                                         // O − M
        float my = oy - spheres[at + 1];
        float mz = oz - spheres[at + 2];
        float a = dd;                                                        // equation 3.6
        float b = 2 * ((dx * mx) + (dy * my) + (dz * mz));                   // equation 3.7
        float c = ((mx * mx) + (my * my) + (mz * mz)) - spheres[at + 3];     // equation 3.8
        return Sphere.smallestRootNotBehind(a, b, b * b - 4 * a * c);
    }

    /**
     * The depth test's distance {@code |P − O|} of the hit at {@code t}, with P = O + t·D
     * rounded as {@link rtd.geometry.Intersection#at} rounds it.
     */
    static float distance(float t, float ox, float oy, float oz, float dx, float dy, float dz) {
        float x = (ox + dx * t) - ox;
        float y = (oy + dy * t) - oy;
        float z = (oz + dz * t) - oz;
        return (float) Math.sqrt(x * x + y * y + z * z);
    }
}
