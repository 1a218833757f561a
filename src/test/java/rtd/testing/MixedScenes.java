package rtd.testing;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Box;
import rtd.geometry.Cone;
import rtd.geometry.Cylinder;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.AreaLight;
import rtd.scene.Light;
import rtd.scene.Scene;

/**
 * Random scenes of every kind of object, the same for the same seed: spheres from tiny to large,
 * triangles (some thin as needles), boxes, a plane or two, overlaps and exact ties; and random
 * rays from inside, around and far outside them.
 */
public final class MixedScenes {

    /**
     * The shapes added after those of {@link #randomObject}, from draws of their own: one for every fourth object or
     * so, some of them exact twins, all after the other objects. So adding a shape here keeps every object of the
     * scenes that the tests' seeds were chosen for, in its place (docs/developers.md, "Adding a shape"); a check that
     * counts hits may still move, where a new shape hides an object. Add its twin too.
     */
    private static final List<LaterShape> LATER = List.of();

    /** A shape of {@link #LATER}: one made from its own draws, around {@code centre}, about {@code size} across. */
    private interface LaterShape {
        IGeometry make(Random random, Vector3f centre, float size);
    }

    private MixedScenes() {
    }

    /** A scene of {@code count} random objects. */
    public static Scene generate(long seed, int count) {
        Random random = new Random(seed);
        List<IGeometry> objects = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            objects.add(randomObject(random, objects));
        }
        for (int planes = random.nextInt(3); planes > 0; planes--) {
            objects.add(random.nextInt(objects.size() + 1) == 0 ? 0 : random.nextInt(objects.size()),
                    new Plane(point(random, 15), direction(random), colour(random), Material.DEFAULT));
        }
        objects.addAll(later(new Random(~seed), count));
        return new Scene(colour(random), new PerspectiveCamera(new Vector3f(0, 0, 40), new Vector3f(0, 0, -1), 60),
                objects);
    }

    /** About {@code count / 4} shapes of {@link #LATER}, one in twelve the twin of one before it. */
    private static List<IGeometry> later(Random random, int count) {
        List<IGeometry> added = new ArrayList<>();
        for (int i = 0; i < count && !LATER.isEmpty(); i++) {
            if (random.nextInt(4) == 0) {
                added.add(!added.isEmpty() && random.nextInt(12) == 0
                        ? twin(added.get(random.nextInt(added.size())), colour(random))
                        : LATER.get(random.nextInt(LATER.size())).make(random, point(random, 12),
                                0.1f + random.nextFloat() * 3));
            }
        }
        return added;
    }

    private static IGeometry randomObject(Random random, List<IGeometry> earlier) {
        if (!earlier.isEmpty() && random.nextInt(12) == 0) {
            return twin(earlier.get(random.nextInt(earlier.size())), colour(random)); // an exact tie
        }
        Vector3f centre = point(random, 12);
        float size = random.nextInt(4) == 0 ? 0.001f + random.nextFloat() * 0.05f : 0.1f + random.nextFloat() * 3;
        switch (random.nextInt(5)) {
            case 0:
                return new Sphere(centre, size, colour(random));
            case 1:
                Vector3f a = centre.add(direction(random).multiply(size));
                Vector3f b = centre.add(direction(random).multiply(size));
                Vector3f c = random.nextInt(5) == 0
                        ? a.add(b.subtract(a).multiply(0.5f)).add(direction(random).multiply(size * 1e-4f)) // a needle
                        : centre.add(direction(random).multiply(size));
                return new Triangle(a, b, c, colour(random), Material.DEFAULT);
            case 3:
                return new Cylinder(centre, centre.add(direction(random).multiply(size)), size * random.nextFloat() + 1e-3f,
                        colour(random), Material.DEFAULT);
            case 4:
                return new Cone(centre, random.nextBoolean() ? 0 : size * random.nextFloat(),
                        centre.add(direction(random).multiply(size)), size * random.nextFloat() + 1e-3f, colour(random),
                        Material.DEFAULT);
            default:
                return Box.between(centre, centre.add(new Vector3f(random.nextFloat() * size + 1e-3f,
                        random.nextFloat() * size + 1e-3f, random.nextFloat() * size + 1e-3f)), colour(random),
                        Material.DEFAULT);
        }
    }

    private static IGeometry twin(IGeometry object, Color colour) {
        return twin(object, colour, Material.DEFAULT);
    }

    private static IGeometry twin(IGeometry object, Color colour, Material material) {
        if (object instanceof Sphere s) {
            return new Sphere(s.center(), s.radius(), colour, material);
        }
        if (object instanceof Triangle t) {
            return new Triangle(t.corner(0), t.corner(1), t.corner(2), colour, material);
        }
        if (object instanceof Plane p) {
            return new Plane(p.point(), p.normal(), colour, material);
        }
        if (object instanceof Box box) {
            return new Box(box.min(), box.max(), colour, material);
        }
        if (object instanceof Cylinder c) {
            return new Cylinder(c.first(), c.second(), c.radius(), colour, material);
        }
        if (object instanceof Cone c) {
            return new Cone(c.first(), c.firstRadius(), c.second(), c.secondRadius(), colour, material);
        }
        throw new IllegalArgumentException("no twin for a " + object.kind() + ": add it here and to LATER");
    }

    /**
     * {@code scene} with random finishes (some mirrors, some glass, some both), one to three
     * coloured lights and, half the time, an area light of up to 3 × 3 samples, the same for the same seed.
     */
    public static Scene shaded(Scene scene, long seed) {
        Random random = new Random(seed);
        List<IGeometry> objects = new ArrayList<>();
        for (IGeometry object : scene.objects()) {
            float reflective = random.nextInt(3) == 0 ? random.nextFloat() : 0;
            float transparency = random.nextInt(4) == 0 ? random.nextFloat() : 0;
            Material material = new Material(random.nextFloat() * 0.3f, random.nextFloat(), random.nextFloat(),
                    1 + random.nextInt(300), reflective, transparency, 1 + random.nextFloat());
            objects.add(twin(object, object.color(), material));
        }
        List<Light> lights = new ArrayList<>();
        for (int i = 0; i <= random.nextInt(3); i++) {
            lights.add(new Light(point(random, 30), new Rgb(random.nextFloat(), random.nextFloat(), random.nextFloat())));
        }
        if (random.nextBoolean()) { // an area light: its samples are point lights that belong together
            lights.addAll(new AreaLight(point(random, 30), direction(random), direction(random), 1 + random.nextInt(3),
                    1 + random.nextInt(3), new Rgb(random.nextFloat(), random.nextFloat(), random.nextFloat())).samples());
        }
        return new Scene(scene.ambient(), scene.camera(), objects, lights);
    }

    /**
     * A random ray: from inside the scene, from around it, or from far away (up to 100,000
     * units), aimed at a random object or anywhere; some directions run along an axis.
     */
    public static Ray ray(Random random, Scene scene) {
        float distance = switch (random.nextInt(4)) {
            case 0 -> 1;
            case 1 -> 30;
            case 2 -> 2_000;
            default -> 100_000;
        };
        Vector3f origin = point(random, distance);
        Vector3f direction;
        if (random.nextBoolean()) {
            IGeometry target = scene.objects().get(random.nextInt(scene.objects().size()));
            Vector3f aim = target.bounds().isBounded() ? target.bounds().centre() : point(random, 10);
            direction = aim.add(point(random, 0.05f)).subtract(origin);
        } else {
            direction = direction(random);
        }
        if (random.nextInt(6) == 0) {
            direction = new Vector3f(direction.x(), 0, random.nextBoolean() ? 0 : direction.z()); // along an axis or a plane
        }
        if (direction.x() == 0 && direction.y() == 0 && direction.z() == 0) {
            direction = new Vector3f(0, 0, -1);
        }
        return new Ray(origin, direction.multiply(random.nextBoolean() ? 1 : 0.3f + random.nextFloat() * 3));
    }

    private static Vector3f point(Random random, float half) {
        return new Vector3f((random.nextFloat() * 2 - 1) * half, (random.nextFloat() * 2 - 1) * half,
                (random.nextFloat() * 2 - 1) * half);
    }

    private static Vector3f direction(Random random) {
        return new Vector3f((float) random.nextGaussian(), (float) random.nextGaussian(), (float) random.nextGaussian());
    }

    private static Color colour(Random random) {
        return new Color(random.nextInt(256), random.nextInt(256), random.nextInt(256));
    }
}
