package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.camera.OrthographicCamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Sphere;
import rtd.math.Vector3f;
import rtd.image.Color;
import rtd.scene.Scene;
import rtd.testing.RandomScenes;

/** Random scenes, written out as text in varied layouts and read back, come back the same. */
@DisplayName("Writing a scene and reading it back")
class SceneRoundTripTest {

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20})
    void givesTheSameScene(long seed) throws SceneException {
        Scene scene = RandomScenes.generate(seed, 50);
        String text = write(scene, new Random(seed));
        Scene back = SceneIO.parseScene("random.txt", text);
        assertThat(back.ambient()).isEqualTo(scene.ambient());
        assertThat(back.objects()).isEqualTo(scene.objects());
        OrthographicCamera camera = (OrthographicCamera) scene.camera();
        OrthographicCamera read = (OrthographicCamera) back.camera();
        assertThat(read.position()).isEqualTo(camera.position());
        assertThat(read.direction()).isEqualTo(camera.direction());
        assertThat(read.zoom()).isEqualTo(camera.zoom());
    }

    /** The scene in the file format, with random blanks, comments and line ends. */
    static String write(Scene scene, Random random) {
        StringBuilder text = new StringBuilder(random.nextBoolean() ? "\uFEFF" : "");
        String newline = random.nextBoolean() ? "\r\n" : "\n";
        OrthographicCamera camera = (OrthographicCamera) scene.camera();
        text.append("// a random scene").append(newline);
        text.append(statement(random, "ambient", colour(scene.ambient()))).append(newline);
        text.append(statement(random, "orthographic_camera", vector(camera.position()), vector(camera.direction()),
                number(camera.zoom()))).append(newline);
        for (IGeometry object : scene.objects()) {
            Sphere sphere = (Sphere) object;
            text.append(statement(random, "sphere", vector(sphere.center()), number(sphere.radius()), colour(sphere.color())));
            text.append(random.nextInt(4) == 0 ? " // a sphere" : "").append(newline);
            text.append(random.nextInt(4) == 0 ? newline : "");
        }
        return text.toString();
    }

    private static String statement(Random random, String keyword, String... groups) {
        StringBuilder text = new StringBuilder(blank(random)).append(keyword);
        for (String group : groups) {
            text.append(blank(random)).append(':').append(blank(random)).append('(').append(blank(random))
                    .append(group.replace("|", blank(random) + "|" + blank(random))).append(blank(random)).append(')');
        }
        return text.toString();
    }

    private static String blank(Random random) {
        return switch (random.nextInt(6)) {
            case 0 -> " ";
            case 1 -> "\t";
            default -> "";
        };
    }

    private static String vector(Vector3f v) {
        return number(v.x()) + "|" + number(v.y()) + "|" + number(v.z());
    }

    private static String number(float f) {
        return Float.toString(f).toLowerCase(Locale.ROOT);
    }

    private static String colour(Color c) {
        return c.red() + "|" + c.green() + "|" + c.blue();
    }
}
