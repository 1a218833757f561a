package rtd.testing;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import rtd.geometry.IGeometry;
import rtd.geometry.Pattern;
import rtd.geometry.Patterned;
import rtd.geometry.Transformed;
import rtd.image.Color;
import rtd.math.Matrix4;
import rtd.scene.Scene;

/**
 * {@link MixedScenes} with most objects transformed (stretched, turned, moved) and some patterned,
 * the same for the same seed: the engine must find the loop's hits on shapes it does not know.
 */
public final class TransformedScenes {

    private TransformedScenes() {
    }

    /** {@code scene}'s objects, about three in four transformed and one in three patterned. */
    public static Scene of(Scene scene, long seed) {
        Random random = new Random(seed);
        List<IGeometry> objects = new ArrayList<>();
        for (IGeometry object : scene.objects()) {
            IGeometry dressed = object;
            if (random.nextInt(3) == 0) {
                Pattern.Kind kind = Pattern.Kind.values()[random.nextInt(4)];
                dressed = new Patterned(dressed, new Pattern(kind, colour(random), colour(random),
                        Matrix4.scale(0.2 + random.nextDouble(), 0.2 + random.nextDouble(), 0.2 + random.nextDouble())));
            }
            if (random.nextInt(4) != 0) {
                dressed = new Transformed(dressed, matrix(random));
            }
            objects.add(dressed);
        }
        return new Scene(scene.ambient(), scene.camera(), objects, scene.lights());
    }

    /** A random scale (some very uneven), turns about each axis and a move. */
    static Matrix4 matrix(Random random) {
        double uneven = random.nextInt(5) == 0 ? 10 : 1;
        return Matrix4.scale(0.3 + random.nextDouble() * uneven, 0.3 + random.nextDouble(), 0.3 + random.nextDouble())
                .then(Matrix4.rotateX(random.nextDouble() * 360)).then(Matrix4.rotateY(random.nextInt(4) * 90))
                .then(Matrix4.rotateZ(random.nextDouble() * 360))
                .then(Matrix4.translate(random.nextGaussian() * 3, random.nextGaussian() * 3, random.nextGaussian() * 3));
    }

    private static Color colour(Random random) {
        return new Color(random.nextInt(256), random.nextInt(256), random.nextInt(256));
    }
}
