package rtd.bench;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import rtd.geometry.Intersection;
import rtd.geometry.Sphere;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.image.Color;

/**
 * The intersection test of section 3.2.2 ({@link Sphere#intersect}) alone, for a ray that hits
 * and one that misses. With {@code -prof gc}, {@code gc.alloc.rate.norm} shows that the
 * {@link Intersection} and the vectors it makes are never allocated once the JIT has inlined
 * the test: the benchmark consumes only primitives.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class SphereIntersectionBenchmark {

    private final Sphere sphere = new Sphere(new Vector3f(0, 0, 0), 2, new Color(255, 0, 0));
    private Ray hitting = new Ray(new Vector3f(0.5f, 0.5f, 20), new Vector3f(0, 0, -1));
    private Ray missing = new Ray(new Vector3f(5, 0.5f, 20), new Vector3f(0, 0, -1));

    @Benchmark
    public float hit() {
        Intersection intersection = sphere.intersect(hitting);
        return intersection.happened() ? intersection.contactCoord().subtract(hitting.origin()).magnitude() : -1;
    }

    @Benchmark
    public float miss() {
        Intersection intersection = sphere.intersect(missing);
        return intersection.happened() ? intersection.contactCoord().subtract(missing.origin()).magnitude() : -1;
    }
}
