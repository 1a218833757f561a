package rtd.scene;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.image.Color;
import rtd.image.Picture;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.LinearTracer;
import rtd.shade.WhittedShader;
import rtd.testing.Cli;
import rtd.testing.GoldenImages;
import rtd.testing.ImageComparison;
import rtd.testing.Scenes;

/**
 * The room with a table and a lamp ({@code examples/lamp_room.txt}): an exact golden at --scale
 * 0.5, and beside it the floor's tiles, the table's full shadow, its penumbra and the shade's
 * shadow on the wall, worked out by hand.
 *
 * <p>The lamp is 16 point lights at x ∈ {−0.3, −0.1, 0.1, 0.3}, z ∈ {−1.8, −1.6, −1.4, −1.2},
 * y = 2.68, each of intensity (255|245|220)/16; the table's top is the box x ∈ [−1.2, 1.2],
 * y ∈ [0.9, 1], z ∈ [−2.2, −0.8]; a floor tile is 0.6 wide, the checker's rule with y just under 0
 * (floor −1): a if floor(x/0.6) + floor(z/0.6) is odd, b (brown) if it is even.
 */
@DisplayName("The example of a room with a table and a lamp")
class LampRoomExampleTest {

    private static Picture picture;

    @BeforeAll
    static void render() {
        picture = BeyondThePaperExamplesTest.renderAtScale("lamp_room", 0.5);
    }

    @Test
    void atScaleHalfItMatchesItsGoldenImageExactly() {
        GoldenImages.assertMatchesGolden("lamp_room", picture.toBufferedImage(), ImageComparison.EXACT);
    }

    /**
     * Seen from straight above, with the tiles' finish (ambient 0.15, diffuse 0.8, specular 0.3,
     * shininess 60, reflective 0.05):
     * <ul>
     * <li>(0|0|−1.5), under the middle of the table, a cream tile (225|215|190): every shadow ray
     *     runs into the top, so only the ambient terms, 0.15·c⊙I = (0.13235|0.12151|0.09642), plus
     *     0.05 of what it mirrors, the table's underside, which faces away from the lamp: its own
     *     ambient 0.15·(140|90|50)⊙I. In all (0.13647|0.12405|0.09769): (35|32|25).</li>
     * <li>(1.9|0|−1.5), beyond the table's edge x = 1.2, a brown tile (120|60|45): the ray to a
     *     light at x_s passes the top's upper edge at x = 1.9 + (x_s − 1.9)/2.68, left of 1.2 for
     *     x_s ≤ −0.1 and right of it for x_s ≥ 0.1: 8 of 16 lit, the penumbra. With the ceiling it
     *     mirrors, which the shade hides from the lamp (ambient 0.3 of (235|230|220)): (62|31|22).</li>
     * <li>(2.5|0|−1.5), a cream tile, every light in view: (0.64793|0.59486|0.47204) from the 16
     *     lights, each with its own N·L and highlight, and the ceiling's share: (169|155|123).</li>
     * </ul>
     */
    @Test
    void theFloorIsInFullShadowUnderTheTableHalfLitAtItsEdgeAndLitBeyond() {
        Scene scene = Scenes.example("lamp_room");
        WhittedShader shader = new WhittedShader(scene, new LinearTracer(scene));
        assertThat(scene.lights()).hasSize(16);
        assertThat(shadeFloor(shader, 0, -1.5f)).as("under the table").isEqualTo(new Color(35, 32, 25));
        assertThat(shadeFloor(shader, 1.9f, -1.5f)).as("in the penumbra").isEqualTo(new Color(62, 31, 22));
        assertThat(shadeFloor(shader, 2.5f, -1.5f)).as("in the light").isEqualTo(new Color(169, 155, 123));
    }

    /**
     * The light is 0.02 under the shade's rim (radius 0.7, the lights at most 0.43 from its axis),
     * so from the back wall above y = 3.1 every shadow ray crosses the rim's plane inside the rim:
     * the wall there gets the ambient term alone, 0.3·(200|190|160)⊙I = (60|54.8|41.4): (60|55|41).
     */
    @Test
    void theShadeHidesTheLampFromTheTopOfTheBackWall() {
        Scene scene = Scenes.example("lamp_room");
        int x = 300;
        int y = 40;
        Ray ray = scene.camera().generateRay(x, y, 960, 540);
        Vector3f onTheWall = ray.pointAt((-6 - ray.origin().z()) / ray.direction().z());
        assertThat(onTheWall.y()).as("height on the back wall").isBetween(3.2f, 4.4f);
        assertThat(onTheWall.x()).as("across the back wall").isBetween(-4.5f, -0.8f);
        assertThat(Color.fromRGB(picture.rgb(x, y))).isEqualTo(new Color(60, 55, 41));
    }

    /** The bottom row sees the floor in front of the table, in the lamp's light: cream and brown tiles as the rule says. */
    @Test
    void eachTileOfTheFloorInFrontIsCreamOrBrownAsTheCheckerSays() {
        Scene scene = Scenes.example("lamp_room");
        int checked = 0;
        for (int x = 7; x < 960; x += 31) {
            Ray ray = scene.camera().generateRay(x, 535, 960, 540);
            Vector3f p = ray.pointAt(-ray.origin().y() / ray.direction().y());
            double u = p.x() / 0.6;
            double w = p.z() / 0.6;
            if (Math.abs(u - Math.rint(u)) < 0.03 || Math.abs(w - Math.rint(w)) < 0.03) {
                continue; // too near a tile's edge to tell by hand
            }
            boolean cream = (Math.floor(u) + Math.floor(w)) % 2 != 0;
            int green = picture.rgb(x, 535) >> 8 & 0xFF;
            if (cream) {
                assertThat(green).as("a cream tile at x = %d", x).isGreaterThan(90);
            } else {
                assertThat(green).as("a brown tile at x = %d", x).isLessThan(60);
            }
            checked++;
        }
        assertThat(checked).isGreaterThan(15);
    }

    /** The loop, the BVH and the grids (the camera's and each of the 16 lights') write the same file, at 240 × 135. */
    @Test
    void theLoopTheBvhAndTheGridsDrawTheSamePicture(@TempDir Path dir) throws IOException {
        byte[] loop = renderSmall(dir, "none");
        assertThat(renderSmall(dir, "bvh")).isEqualTo(loop);
        assertThat(renderSmall(dir, "grid")).isEqualTo(loop);
    }

    private static byte[] renderSmall(Path dir, String accel) throws IOException {
        Path out = dir.resolve(accel + ".png");
        Cli.Run run = Cli.run("examples/lamp_room.txt", "-o", out.toString(), "--scale", "0.125", "--accel", accel,
                "--threads", "2", "--no-progress");
        assertThat(run.exitCode()).as(run.err()).isZero();
        return Files.readAllBytes(out);
    }

    /** The colour of the floor at (x|0|z) seen from straight above it, from just over the floor. */
    private static Color shadeFloor(WhittedShader shader, float x, float z) {
        return shader.colourAt(new Ray(new Vector3f(x, 0.01f, z), new Vector3f(0, -1, 0)), WhittedShader.BOUNCES)
                .toColor();
    }
}
