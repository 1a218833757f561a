package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.IntStream;
import javax.imageio.ImageIO;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.accel.Accelerator;

/**
 * rtd's promise to a student: an edit of the paper's equations shows in every picture. This
 * test makes the edit the README suggests, equation 3.8 with half the squared radius (a smaller
 * sphere), compiles the changed {@code Sphere.java} against the packaged jar, puts it before the
 * jar on the class path, and draws the paper's scene and its lit twin on every path: each
 * picture must equal the paper's loop ({@code --accel none}) with the edit, and differ from the
 * picture without it; {@code --explain} must show the edited c.
 */
@DisplayName("A student's edit of the sphere's equation 3.8")
class StudentEditIT {

    private static final Path SPHERE = Path.of("src/main/java/rtd/geometry/Sphere.java");
    private static final String EQUATION_3_8 = "float c = (cx * cx + cy * cy + cz * cz) - r * r;";
    private static final String EDITED = "float c = (cx * cx + cy * cy + cz * cz) - 0.5f * r * r;";
    private static final String JAR = System.getProperty("rtd.jar", "target/rtd.jar");

    /** The pictures drawn so far, by {@link #render}'s arguments. */
    private static final Map<String, int[]> DRAWN = new ConcurrentHashMap<>();

    @TempDir
    static Path work;
    private static Path edited;

    @BeforeAll
    static void compileTheEditedSphere() throws IOException {
        String source = Files.readString(SPHERE);
        assertThat(source).as("Sphere.java no longer holds the line this test edits; update EQUATION_3_8")
                .contains(EQUATION_3_8);
        Path sources = Files.createDirectories(work.resolve("src/rtd/geometry"));
        Files.writeString(sources.resolve("Sphere.java"), source.replace(EQUATION_3_8, EDITED));
        edited = Files.createDirectories(work.resolve("classes"));
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        int status = javac.run(null, null, null, "--release", "17", "-cp", JAR, "-d", edited.toString(),
                sources.resolve("Sphere.java").toString());
        assertThat(status).as("javac of the edited Sphere.java").isZero();
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"--paper", "--accel auto", "--accel bvh", "--accel grid",
            "--accel bvh --threads 1", "--accel grid --threads 1"})
    void theFlatPictureOfEveryPathShowsTheEdit(String path) throws Exception {
        assertShowsTheEdit("examples/input_rtd.txt", path, "--accel none");
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"--accel auto", "--accel bvh", "--accel grid"})
    void theAntiAliasedPictureOfEveryPathShowsTheEdit(String path) throws Exception {
        assertShowsTheEdit("examples/input_rtd.txt", path + " --samples 2", "--accel none --samples 2");
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"--accel auto", "--accel bvh", "--accel grid"})
    void theShadedPictureOfEveryPathShowsTheEdit(String path) throws Exception {
        assertShowsTheEdit("examples/lit_paper.txt", path, "--accel none");
    }

    @Test
    void theImageOfHitsOfAFlatPictureOfManySpheresShowsTheEdit() throws Exception {
        StringBuilder scene = new StringBuilder("ambient:(0|0|0)\northographic_camera:(0|0|20):(0|0|-1):(50)\n");
        for (int i = 0; i < Accelerator.IMAGE_THRESHOLD; i++) { // a wall of 400 × 250 spheres, some before others
            scene.append(String.format(java.util.Locale.ROOT, "sphere:(%.3f|%.3f|%d):(%.2f):(%d|%d|200)%n",
                    i % 400 * 0.095 - 19, i / 400 * 0.08 - 10, i * 7919 % 10, 0.05 + i % 7 * 0.02, i % 256, i / 400));
        }
        Path many = work.resolve("many_spheres.txt");
        Files.writeString(many, scene);
        assertThat(run(true, many.toString(), "--accel", "auto", "--stats", "-o", work.resolve("s.png").toString()))
                .contains("image of hits in");
        assertShowsTheEdit(many.toString(), "--accel auto", "--accel bvh"); // the BVH shows the edit as the loop does
    }

    @Test
    void theMirroredRaysOfTheGlassExampleShowTheEdit() throws Exception {
        // its floor mirrors the spheres: the mirrored rays find them through the BVH, behind the lights' grids
        // (grid: auto builds none for so few objects)
        assertShowsTheEdit("examples/glass_and_mirror.txt", "--accel grid", "--accel none");
    }

    /** The picture {@code path} draws with the edit is the loop's with the edit, and not the loop's without it. */
    private static void assertShowsTheEdit(String scene, String path, String loop) throws Exception {
        int[] editedLoop = render(true, scene, loop);
        assertThat(differingPixels(render(true, scene, path), editedLoop)).as("pixels unlike the edited loop's").isZero();
        assertThat(differingPixels(render(false, scene, loop), editedLoop)).as("pixels the edit changes").isPositive();
    }

    @Test
    void explainShowsTheEditedCoefficient() throws Exception {
        // the red sphere: M = (-10|1|5), r = 5; the ray of the middle pixel (96, 54) of the
        // 192 × 108 picture starts at the camera, (0|0|20): O − M = (10|−1|15), |O − M|² = 326,
        // so c = 326 − 0.5·25 = 313.5 (unedited: 326 − 25 = 301)
        String explained = run(true, "examples/input_rtd.txt", "--explain", "96,54");
        assertThat(explained).contains("c = (O − M)·(O − M) − r² = 313.5").doesNotContain("= 301   (equation 3.8)");
    }

    /**
     * The pixels of {@code scene} drawn with {@code options}, with or without the edit; each picture is drawn once, as
     * the loop's pictures are the same for every path compared with them.
     */
    private static int[] render(boolean withEdit, String scene, String options) throws Exception {
        String key = withEdit + " " + scene + " " + options;
        int[] drawn = DRAWN.get(key);
        if (drawn == null) {
            drawn = draw(withEdit, scene, options);
            DRAWN.put(key, drawn);
        }
        return drawn;
    }

    private static int[] draw(boolean withEdit, String scene, String options) throws Exception {
        Path out = Files.createTempFile(work, "picture", ".png");
        Files.delete(out);
        List<String> args = new ArrayList<>(List.of(options.split(" ")));
        args.addAll(List.of("-o", out.toString()));
        run(withEdit, scene, args.toArray(String[]::new));
        BufferedImage image = ImageIO.read(out.toFile());
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    private static String run(boolean withEdit, String scene, String... options) throws Exception {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", (withEdit ? edited + File.pathSeparator : "") + JAR, "rtd.cli.RtdCommand", scene,
                "--scale", "0.1", "--no-progress"));
        command.addAll(List.of(options));
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        String output = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(process.waitFor(60, TimeUnit.SECONDS)).isTrue();
        assertThat(process.exitValue()).as(output).isZero();
        return output;
    }

    private static long differingPixels(int[] a, int[] b) {
        assertThat(a).hasSameSizeAs(b);
        return IntStream.range(0, a.length).filter(i -> a[i] != b[i]).count();
    }
}
