package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;
import static rtd.accel.Grazing.missesExactly;
import static rtd.accel.Grazing.tinySpheres;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.accel.Accelerator.Choice;
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
import rtd.shade.Surface;
import rtd.shade.WhittedShader;
import rtd.testing.MixedScenes;

/**
 * The rays the shader reflects off a flat mirror, as it makes them (from {@link Surface#over}), get the paper's loop's
 * hit to the last bit through the tracers that {@code --accel grid} chains: random scenes of every kind of object over
 * a tilted mirror, and tiny spheres where rounding lets the test report hits beside them.
 */
@DisplayName("The rays a mirror reflects get the loop's hit through the engine's tracers")
class MirroredRaysTest {

    private static final Material MIRROR = new Material(0.1f, 0.6f, 0.3f, 50, 0.5f, 0, 1);
    private static final Light LIGHT = new Light(new Vector3f(0, 200, 0), new Rgb(1, 1, 1));

    /** The ray the shader reflects at {@code hit} of {@code ray} ({@link WhittedShader}'s step 4). */
    private static Ray mirrored(Ray ray, Hit hit) {
        Surface surface = Surface.at(ray, hit);
        Vector3f direction = ray.direction();
        Vector3f normal = surface.normal();
        return new Ray(surface.over(), direction.subtract(normal.multiply(2 * direction.dot(normal))));
    }

    /** Checks {@code ray} through {@code tracer} against the loop, to the last bit. */
    private static void check(Scene scene, Tracer tracer, Ray ray) {
        Hit loop = scene.nearestHit(ray);
        Hit traced = tracer.nearestHit(ray);
        if (loop == null) {
            assertThat(traced).as("ray " + ray).isNull();
            return;
        }
        assertThat(traced).as("ray " + ray).isNotNull();
        assertThat(traced.index()).as("object hit by " + ray).isEqualTo(loop.index());
        assertThat(Float.floatToIntBits(traced.t())).as("t of " + ray).isEqualTo(Float.floatToIntBits(loop.t()));
        assertThat(traced.distance()).as("distance of " + ray).isEqualTo(loop.distance());
    }

    private static Tracer gridTracers(Scene scene) {
        return Accelerator.of(scene, Choice.grid, 400, 300, 1, 1).tracers().get();
    }

    @ParameterizedTest(name = "random scene {0}")
    @ValueSource(longs = {1, 2, 4, 5, 6, 7})
    void everyRayTheShaderMirrorsGetsTheLoopsHit(long seed) {
        Random random = new Random(seed);
        List<IGeometry> objects = new ArrayList<>(MixedScenes.generate(seed, 300).objects());
        if (seed % 2 == 0) {
            objects.removeIf(object -> object instanceof Plane); // and with the random planes, in the odd ones
        }
        Vector3f tilt = new Vector3f((float) random.nextGaussian() * 0.15f, 1, (float) random.nextGaussian() * 0.15f);
        objects.add(random.nextInt(objects.size()), new Plane(new Vector3f(0, -16, 0), tilt.normalize(),
                new Color(200, 200, 200), MIRROR));
        PerspectiveCamera camera = new PerspectiveCamera(new Vector3f((random.nextFloat() * 2 - 1) * 20,
                20 + random.nextFloat() * 20, 40), new Vector3f(0, -0.7f, -1), 60);
        Scene scene = new Scene(new Color(0, 0, 0), camera, objects, List.of(LIGHT));
        Tracer tracer = gridTracers(scene);

        int mirrored = 0;
        for (int i = 0; i < 20_000; i++) {
            Ray ray = camera.generateRay(random.nextFloat() * 400, random.nextFloat() * 300, 400, 300);
            Hit hit = scene.nearestHit(ray);
            if (hit != null && hit.object() instanceof Plane plane && plane.material() == MIRROR) {
                check(scene, tracer, mirrored(ray, hit));
                mirrored++;
            }
        }

        assertThat(mirrored).as("mirrored rays checked").isGreaterThan(1_000);
    }

    @Test
    void mirroredRaysPastTinySpheresGetTheLoopsHitWhereRoundingMakesHitsBesideThem() {
        Random random = new Random(7);
        List<IGeometry> objects = tinySpheres(random);
        objects.add(new Plane(new Vector3f(0, 0, 0), new Vector3f(0, 1, 0), new Color(200, 200, 200), MIRROR));
        Vector3f eye = new Vector3f(0.5f, 10, 0.25f);
        Vector3f image = new Vector3f(0.5f, -10, 0.25f); // the eye mirrored in the plane y = 0
        PerspectiveCamera camera = new PerspectiveCamera(eye, new Vector3f(0, -1, 0), 60);
        Scene scene = new Scene(new Color(0, 0, 0), camera, objects, List.of(LIGHT));
        Tracer tracer = gridTracers(scene);

        int mirrored = 0;
        int besides = 0;
        for (int i = 0; i < 6_000; i++) {
            Sphere target = (Sphere) objects.get(random.nextInt(400));
            // the camera ray towards the mirror's point on the line from the eye's image past the sphere, off by up
            // to 20 radii
            Vector3f aim = target.center().add(new Vector3f(random.nextFloat() * 2 - 1, 0, random.nextFloat() * 2 - 1)
                    .multiply(target.radius() * 20 * random.nextFloat()));
            Vector3f towards = aim.subtract(image);
            Vector3f onMirror = image.add(towards.multiply(-image.y() / towards.y()));
            Ray ray = new Ray(eye, onMirror.subtract(eye));
            Hit hit = scene.nearestHit(ray);
            if (hit == null || !(hit.object() instanceof Plane)) {
                continue;
            }
            Ray reflected = mirrored(ray, hit);
            check(scene, tracer, reflected);
            mirrored++;
            Hit loop = scene.nearestHit(reflected);
            if (loop != null && loop.object() instanceof Sphere sphere && missesExactly(reflected, sphere)) {
                besides++;
            }
        }

        assertThat(besides).as("hits the loop reports beside a sphere").isGreaterThan(0);
        assertThat(mirrored).isGreaterThan(5_000);
    }
}
