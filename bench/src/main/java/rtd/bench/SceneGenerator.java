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
 * file. Its twin for POV-Ray 3.7 is written by rtd itself ({@code --export-pov}, see bench/run.sh).
 *
 * <p>The camera is the paper's: at (0|0|20), looking along −z, 50 pixels per unit, so that the
 * 1920 × 1080 picture shows x in ±19.2 and y in ±10.8. The spheres fill that view and z in
 * ±10; their radius shrinks as N grows (0.5 to 1.5 times 3/∛N), so that every scene is
 * about equally full.
 *
 * <p>Usage: {@code java -cp bench/target/benchmarks.jar rtd.bench.SceneGenerator N SEED OUT.txt [shaded]}.
 * With {@code shaded} it writes the shaded benchmark instead: the same spheres above a mirroring
 * floor, two lights, a perspective camera, and no POV-Ray twin (make that with rtd's
 * {@code --export-pov}).
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
        if (args.length > 3 && args[3].equals("shaded")) {
            writeShaded(count, seed, out);
            return;
        }
        write(count, seed, out);
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

    static void write(int count, long seed, Path rtdFile) throws IOException {
        try (BufferedWriter rtd = Files.newBufferedWriter(rtdFile, StandardCharsets.UTF_8)) {
            rtd.write("// " + count + " random spheres, seed " + seed + " (bench/run.sh)\n");
            rtd.write("ambient:(16|18|28)\n");
            rtd.write("orthographic_camera:(0|0|20):(0|0|-1):(50)\n");
            for (Ball b : balls(count, seed)) {
                rtd.write(String.format(Locale.ROOT, "sphere:(%s|%s|%s):(%s):(%d|%d|%d)%n",
                        num(b.x()), num(b.y()), num(b.z()), num(b.r()), b.red(), b.green(), b.blue()));
            }
        }
    }

    /** The spheres above a floor that mirrors them, lit by two lights, seen from above and in front. */
    static void writeShaded(int count, long seed, Path rtdFile) throws IOException {
        try (BufferedWriter rtd = Files.newBufferedWriter(rtdFile, StandardCharsets.UTF_8)) {
            rtd.write("// " + count + " random spheres on a mirroring floor, two lights, seed " + seed + " (bench/beyond.sh)\n");
            rtd.write("ambient:(16|18|28)\n");
            rtd.write("perspective_camera:(0|22|42):(0|-0.55|-1):(62)\n");
            rtd.write("material:(floor):(ambient=0.1|diffuse=0.6|specular=0.3|shininess=50|reflective=0.5)\n");
            rtd.write("material:(ball):(ambient=0.1|diffuse=0.8|specular=0.6|shininess=120)\n");
            rtd.write("plane:(0|-11|0):(0|1|0):(200|200|200):(floor)\n");
            rtd.write("light:(-30|40|30):(200|190|170)\n");
            rtd.write("light:(35|25|10):(90|110|160)\n");
            for (Ball b : balls(count, seed)) {
                rtd.write(String.format(Locale.ROOT, "sphere:(%s|%s|%s):(%s):(%d|%d|%d):(ball)%n",
                        num(b.x()), num(b.y()), num(b.z()), num(b.r()), b.red(), b.green(), b.blue()));
            }
        }
    }

    private static String num(float value) {
        String text = Float.toString(value);
        return text.endsWith(".0") ? text.substring(0, text.length() - 2) : text;
    }
}
