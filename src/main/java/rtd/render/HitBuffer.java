package rtd.render;

import java.util.Arrays;
import java.util.List;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.math.Ray;

/**
 * The nearest hits of the rays of a {@link RayBundle}, kept as numbers: for ray {@code i} the place of the object hit
 * among the scene's objects (−1: none), t, the distance {@code |P − O|}, and the intersection tests the tracer ran to
 * find it ({@code --view cost}). A {@link Tracer} fills it, a {@link Shader} reads it; a {@link Hit} record is made
 * only where a shader asks for one.
 */
public final class HitBuffer {

    private final int[] index;
    private final float[] t;
    private final float[] distance;
    private final int[] tests;
    /** Whether the last {@link #setMisses} has not been followed by a {@link #set}: every ray missed. */
    private boolean missedAll;
    /**
     * The entries {@link #setMisses} answered at once and not yet written: most of the paper's picture is answered so,
     * and a flat shader colours such a bundle without reading an entry, which saves four passes over the arrays.
     */
    private int pending;

    public HitBuffer(int capacity) {
        index = new int[capacity];
        t = new float[capacity];
        distance = new float[capacity];
        tests = new int[capacity];
    }

    /** Ray {@code i} took {@code count} intersection tests (every tracer sets this for each ray it traces). */
    public void setTests(int i, long count) {
        writePending();
        tests[i] = (int) Math.min(Integer.MAX_VALUE, count);
    }

    public int tests(int i) {
        writePending();
        return tests[i];
    }

    /** Ray {@code i} hits object {@code object} (its place in the scene) at {@code t}, at {@code distance} from O. */
    public void set(int i, int object, float t, float distance) {
        writePending();
        missedAll = false;
        this.index[i] = object;
        this.t[i] = t;
        this.distance[i] = distance;
    }

    /**
     * Rays {@code i} to {@code i + count − 1} hit what {@code index}, {@code t} and {@code distance} hold from
     * {@code from} on, as {@link #set(int, int, float, float)} sets one, and took the tests {@code tests} holds there.
     */
    public void set(int i, int count, int from, int[] index, float[] t, float[] distance, int[] tests) {
        writePending();
        missedAll = false;
        System.arraycopy(index, from, this.index, i, count);
        System.arraycopy(t, from, this.t, i, count);
        System.arraycopy(distance, from, this.distance, i, count);
        System.arraycopy(tests, from, this.tests, i, count);
    }

    /** Ray {@code i} hits {@code hit}, or nothing if it is {@code null}. */
    public void set(int i, Hit hit) {
        if (hit == null) {
            set(i, -1, Float.NaN, Float.POSITIVE_INFINITY);
        } else {
            set(i, hit.index(), hit.t(), hit.distance());
        }
    }

    /** Rays 0 to {@code count − 1} hit nothing, and took no intersection test. */
    public void setMisses(int count) {
        missedAll = true;
        pending = count;
    }

    /** Whether a tracer said at once that no ray hit anything ({@link #setMisses}); {@code false} says nothing. */
    public boolean missedAll() {
        return missedAll;
    }

    private void writePending() {
        if (pending == 0) {
            return;
        }
        int count = pending;
        pending = 0;
        Arrays.fill(tests, 0, count, 0);
        Arrays.fill(t, 0, count, Float.NaN);
        Arrays.fill(index, 0, count, -1);
        Arrays.fill(distance, 0, count, Float.POSITIVE_INFINITY);
    }

    /** The place of the object ray {@code i} hits among the scene's objects, or −1. */
    public int index(int i) {
        writePending();
        return index[i];
    }

    /** The distance {@code |P − O|} of ray {@code i}'s hit, infinite if none. */
    public float distance(int i) {
        writePending();
        return distance[i];
    }

    public Hit hit(int i, RayBundle rays, List<IGeometry> objects) {
        return hit(i, rays.ray(i), objects);
    }

    /** Ray {@code i}'s hit as a record, its point as the intersection test computes it; {@code null} if none. */
    public Hit hit(int i, Ray ray, List<IGeometry> objects) {
        writePending();
        if (index[i] < 0) {
            return null;
        }
        return new Hit(objects.get(index[i]), index[i], t[i], distance[i], ray.pointAt(t[i]));
    }
}
