package rtd.bench;

import java.util.ArrayList;
import java.util.List;
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
import rtd.accel.LightGrids;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.Tracer;
import rtd.scene.Light;
import rtd.scene.Scene;

/**
 * Shadow rays of the shaded benchmark's scene (N random spheres of {@link SceneGenerator} above a
 * floor, two lights), from the points the camera sees (every fourth pixel of each fourth row of
 * 1920 × 1080) to each light, answered by the tree ({@code bvh}) and by the light grids with the
 * tree for the rays they do not serve ({@code lightGrids}). The score is nanoseconds per shadow
 * ray.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
public class ShadowBenchmark {

    private static final int BATCH = 4096;

    @Param({"1000", "100000"})
    public int spheres;

    private Tracer bvh;
    private Tracer lightGrids;
    private Ray[] rays;
    private float[] distances;
    private int next;

    @Setup(Level.Trial)
    public void setUp() {
        List<IGeometry> objects = new ArrayList<>();
        objects.add(new Plane(new Vector3f(0, -11, 0), new Vector3f(0, 1, 0), new Color(200, 200, 200), Material.DEFAULT));
        for (SceneGenerator.Ball b : SceneGenerator.balls(spheres, 42)) {
            objects.add(new Sphere(new Vector3f(b.x(), b.y(), b.z()), b.r(), new Color(b.red(), b.green(), b.blue())));
        }
        List<Light> lights = List.of(new Light(new Vector3f(-30, 40, 30), new Rgb(0.8f, 0.75f, 0.7f)),
                new Light(new Vector3f(35, 25, 10), new Rgb(0.35f, 0.43f, 0.63f)));
        PerspectiveCamera camera = new PerspectiveCamera(new Vector3f(0, 22, 42), new Vector3f(0, -0.55f, -1), 62);
        Scene scene = new Scene(new Color(16, 18, 28), camera, objects, lights);
        Bvh tree = Bvh.build(scene);
        bvh = tree.newTracer();
        lightGrids = LightGrids.build(scene, BenchScenes.WIDTH, BenchScenes.HEIGHT, 1, 1).newTracer(tree.newTracer());
        shadowRays(scene, camera, tree.newTracer());
    }

    /** From the points the camera sees, a little off the surface as the shader starts them, to each light. */
    private void shadowRays(Scene scene, PerspectiveCamera camera, Tracer tracer) {
        List<Ray> made = new ArrayList<>();
        List<Float> lengths = new ArrayList<>();
        for (int y = 0; y < BenchScenes.HEIGHT; y += 4) {
            for (int x = 0; x < BenchScenes.WIDTH; x += 4) {
                Ray eye = camera.generateRay(x, y, BenchScenes.WIDTH, BenchScenes.HEIGHT);
                Hit hit = tracer.nearestHit(eye);
                if (hit == null) {
                    continue;
                }
                Vector3f over = hit.point().add(hit.normal(eye.direction()).multiply(1e-3f));
                for (Light light : scene.lights()) {
                    Vector3f toLight = light.position().subtract(over);
                    made.add(new Ray(over, toLight));
                    lengths.add(toLight.magnitude());
                }
            }
        }
        rays = made.toArray(Ray[]::new);
        distances = new float[lengths.size()];
        for (int i = 0; i < distances.length; i++) {
            distances[i] = lengths.get(i);
        }
    }

    @Benchmark
    @OperationsPerInvocation(BATCH)
    public int bvh() {
        return answer(bvh);
    }

    @Benchmark
    @OperationsPerInvocation(BATCH)
    public int lightGrids() {
        return answer(lightGrids);
    }

    private int answer(Tracer tracer) {
        int blocked = 0;
        for (int k = 0; k < BATCH; k++) {
            next = next + 1 < rays.length ? next + 1 : 0;
            blocked += tracer.blocked(rays[next], distances[next]) ? 1 : 0;
        }
        return blocked;
    }
}
