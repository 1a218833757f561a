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
import rtd.accel.Bvh;
import rtd.accel.ViewGrid;
import rtd.camera.OrthographicCamera;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.render.Tracer;
import rtd.scene.Scene;

/**
 * One ray per pixel of a 1920 × 1080 image, made and traced as the renderer does it, row by
 * row, through the bounding volume hierarchy one ray at a time ({@code bvh}) and in 8 × 8
 * squares ({@code bvhSquares}), and through the view grid in 8 × 8 squares ({@code gridSquares},
 * as the renderer does for these flat scenes), for random scenes of N spheres (those of
 * {@link SceneGenerator}). The score is nanoseconds per ray; {@link PaperLoopBenchmark} is the
 * same for the paper's loop.
 * With {@code -prof gc}, {@code gc.alloc.rate.norm} is the bytes allocated per ray.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class TraceBenchmark {

    @Param({"10", "1000", "100000", "1000000"})
    public int spheres;

    private Scene scene;
    private OrthographicCamera camera;
    private Tracer bvh;
    private Tracer grid;
    private int row;
    private int band;
    private final RayBundle rays = new RayBundle(64);
    private final HitBuffer hits = new HitBuffer(64);

    @Setup(Level.Trial)
    public void setUp() {
        scene = BenchScenes.randomSpheres(spheres);
        camera = (OrthographicCamera) scene.camera(); // the grid serves its own camera's rays
        bvh = Bvh.build(scene).newTracer();
        grid = ViewGrid.build(scene, BenchScenes.WIDTH, BenchScenes.HEIGHT, 1, 1).newTracer();
    }

    @Benchmark
    @OperationsPerInvocation(BenchScenes.WIDTH)
    public int bvh() {
        return traceRow(bvh);
    }

    /** The renderer's way: 8 × 8 squares of parallel rays share one walk down the tree. */
    @Benchmark
    @OperationsPerInvocation(8 * BenchScenes.WIDTH)
    public int bvhSquares() {
        band = (band + 1) % (BenchScenes.HEIGHT / 8);
        return BenchScenes.traceBand(bvh, camera, 8 * band, rays, hits);
    }

    /** The view grid: each ray tests its cell's spheres, nearest first, until one lies beyond its hit. */
    @Benchmark
    @OperationsPerInvocation(8 * BenchScenes.WIDTH)
    public int gridSquares() {
        band = (band + 1) % (BenchScenes.HEIGHT / 8);
        return BenchScenes.traceBand(grid, camera, 8 * band, rays, hits);
    }

    private int traceRow(Tracer tracer) {
        row = (row + 7) % BenchScenes.HEIGHT; // rows spread over the image, not the same one
        return BenchScenes.traceRow(tracer, camera, row);
    }
}
