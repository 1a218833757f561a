package rtd.bench;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.SplittableRandom;

/**
 * Writes a benchmark scene of N random spheres, the same for the same seed, as an rtd scene
 * file and, beside it, the same scene for POV-Ray 3.7.
 *
 * <p>The camera is the paper's: at (0|0|20), looking along −z, 50 pixels per unit, so that the
 * 1920 × 1080 picture shows x in ±19.2 and y in ±10.8. The spheres fill that view and z in
 * ±10; their radius shrinks as N grows (0.5 to 1.5 times 3/∛N), so that every scene is
 * about equally full.
 *
 * <p>Usage: {@code java -cp bench/target/benchmarks.jar rtd.bench.SceneGenerator N SEED OUT.txt}
 */
public final class SceneGenerator {

    static final float HALF_WIDTH = 19.2f;
    static final float HALF_HEIGHT = 10.8f;
    static final float HALF_DEPTH = 10f;

    private SceneGenerator() {
    }

    public static void main(String[] args) throws IOException {
        int count = Integer.parseInt(args[0]);
        long seed = Long.parseLong(args[1]);
        Path out = Path.of(args[2]);
        write(count, seed, out, Path.of(out.toString().replaceAll("\\.txt$", "") + ".pov"));
    }

    /** One sphere: centre, radius and colour. */
    record Ball(float x, float y, float z, float r, int red, int green, int blue) {
    }

    /** The i-th sphere of the scene of {@code count} spheres with {@code seed}, in order. */
    static Ball[] balls(int count, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        float scale = (float) (3 / Math.cbrt(count));
        Ball[] balls = new Ball[count];
        for (int i = 0; i < count; i++) {
            balls[i] = new Ball(round(uniform(random, HALF_WIDTH), 1000), round(uniform(random, HALF_HEIGHT), 1000),
                    round(uniform(random, HALF_DEPTH), 1000), round(scale * (0.5f + (float) random.nextDouble()), 10000),
                    random.nextInt(256), random.nextInt(256), random.nextInt(256));
        }
        return balls;
    }

    private static float uniform(SplittableRandom random, float half) {
        return (float) ((random.nextDouble() * 2 - 1) * half);
    }

    /** Rounds to the decimals the file keeps, so that rtd and POV-Ray see the same numbers. */
    private static float round(float value, int factor) {
        return (float) (Math.round(value * (double) factor) / (double) factor);
    }

    static void write(int count, long seed, Path rtdFile, Path povFile) throws IOException {
        Ball[] balls = balls(count, seed);
        try (BufferedWriter rtd = Files.newBufferedWriter(rtdFile, StandardCharsets.UTF_8);
                BufferedWriter pov = Files.newBufferedWriter(povFile, StandardCharsets.UTF_8)) {
            rtd.write("// " + count + " random spheres, seed " + seed + " (bench/run.sh)\n");
            rtd.write("ambient:(16|18|28)\n");
            rtd.write("orthographic_camera:(0|0|20):(0|0|-1):(50)\n");
            pov.write("// " + count + " random spheres, seed " + seed + ": the rtd scene of the same name\n");
            pov.write("#version 3.7;\nglobal_settings { assumed_gamma 1.0 ambient_light 1 }\n");
            pov.write("background { rgb <16/255, 18/255, 28/255> }\n");
            // POV-Ray is left-handed: its z runs into the picture, so rtd's z changes sign.
            pov.write("camera { orthographic location <0, 0, -20> direction <0, 0, 1> right x*38.4 up y*21.6 }\n");
            pov.write("#default { finish { ambient 1 diffuse 0 } }\n");
            for (Ball b : balls) {
                rtd.write(String.format(Locale.ROOT, "sphere:(%s|%s|%s):(%s):(%d|%d|%d)%n",
                        num(b.x()), num(b.y()), num(b.z()), num(b.r()), b.red(), b.green(), b.blue()));
                pov.write(String.format(Locale.ROOT, "sphere { <%s, %s, %s>, %s pigment { rgb <%s, %s, %s> } }%n",
                        num(b.x()), num(b.y()), num(-b.z()), num(b.r()),
                        num(b.red() / 255f), num(b.green() / 255f), num(b.blue() / 255f)));
            }
        }
    }

    private static String num(float value) {
        String text = Float.toString(value);
        return text.endsWith(".0") ? text.substring(0, text.length() - 2) : text;
    }
}
