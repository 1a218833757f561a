package rtd.bench;

import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import rtd.camera.OrthographicCamera;
import rtd.render.LinearTracer;
import rtd.render.Tracer;
import rtd.scene.Scene;

/**
 * One ray per pixel of a 1920 × 1080 image, made and traced as the renderer does it, row by
 * row, with the paper's loop over every object (Listing 4.3, {@link LinearTracer}), for random
 * scenes of N spheres. The score is nanoseconds per ray; it grows with N, where the
 * hierarchy's of {@link TraceBenchmark} grows with log N.
 * With {@code -prof gc}, {@code gc.alloc.rate.norm} is the bytes allocated per ray.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class PaperLoopBenchmark {

    @Param({"10", "1000"})
    public int spheres;

    private Scene scene;
    private OrthographicCamera camera;
    private Tracer linear;
    private int row;

    @Setup(Level.Trial)
    public void setUp() {
        scene = BenchScenes.randomSpheres(spheres);
        camera = BenchScenes.paperCamera();
        linear = new LinearTracer(scene);
    }

    @Benchmark
    @OperationsPerInvocation(BenchScenes.WIDTH)
    public int linear() {
        return traceRow(linear);
    }

    private int traceRow(Tracer tracer) {
        row = (row + 7) % BenchScenes.HEIGHT; // rows spread over the image, not the same one
        return BenchScenes.traceRow(tracer, camera, row);
    }
}
