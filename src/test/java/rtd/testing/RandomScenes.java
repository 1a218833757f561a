package rtd.testing;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import rtd.camera.OrthographicCamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Sphere;
import rtd.math.Vector3f;
import rtd.image.Color;
import rtd.scene.Scene;

/** Random scenes from a seed: oblique cameras, spheres of all sizes, overlaps and exact ties. */
public final class RandomScenes {

    private RandomScenes() {
    }

    /** A random scene with {@code count} spheres, the same for the same seed. */
    public static Scene generate(long seed, int count) {
        Random random = new Random(seed);
        float distance = random.nextBoolean() ? 30 : 30 * (1 << random.nextInt(6));
        Vector3f direction = new Vector3f(gauss(random), gauss(random), gauss(random));
        if (random.nextInt(8) == 0) {
            direction = new Vector3f(0, random.nextBoolean() ? -1 : 1, 0); // straight down or up
        }
        Vector3f position = direction.normalize().multiply(-distance);
        float zoom = 4 + random.nextFloat() * 10;
        OrthographicCamera camera = new OrthographicCamera(position, direction, zoom);
        List<IGeometry> spheres = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            if (i > 0 && random.nextInt(10) == 0) {
                Sphere twin = (Sphere) spheres.get(random.nextInt(spheres.size()));
                spheres.add(new Sphere(twin.center(), twin.radius(), randomColour(random))); // an exact tie
                continue;
            }
            Vector3f centre = new Vector3f(uniform(random, 12), uniform(random, 8), uniform(random, 12));
            float radius = random.nextInt(4) == 0 ? 0.001f + random.nextFloat() * 0.05f : 0.1f + random.nextFloat() * 3;
            spheres.add(new Sphere(centre, radius, randomColour(random)));
        }
        return new Scene(randomColour(random), camera, spheres);
    }

    private static float gauss(Random random) {
        return (float) random.nextGaussian();
    }

    private static float uniform(Random random, float half) {
        return (random.nextFloat() * 2 - 1) * half;
    }

    private static Color randomColour(Random random) {
        return new Color(random.nextInt(256), random.nextInt(256), random.nextInt(256));
    }
}
