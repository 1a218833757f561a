package rtd.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.geometry.IGeometry;
import rtd.image.Picture;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.testing.GoldenImages;
import rtd.testing.ImageComparison;
import rtd.testing.Scenes;

/**
 * The examples of patterns and transformations: exact goldens at half size (--scale 0.5), each
 * with facts worked out by hand beside it.
 */
@DisplayName("The examples of patterns and transformations")
class PartThreeExamplesTest {

    @ParameterizedTest(name = "{0} at --scale 0.5 matches its golden image exactly")
    @ValueSource(strings = {"whitted_1980", "ellipsoid_and_tilted_box"})
    void matchesItsGoldenImageExactly(String name) {
        Picture picture = BeyondThePaperExamplesTest.renderAtScale(name, 0.5);
        GoldenImages.assertMatchesGolden(name, picture.toBufferedImage(), ImageComparison.EXACT);
    }

    @Test
    void inWhittedsPictureTheSkyIsTheAmbientColourAndEachTileOneOfTheTwoColours() {
        Scene scene = Scenes.example("whitted_1980");
        Picture picture = BeyondThePaperExamplesTest.renderAtScale("whitted_1980", 0.5);
        assertThat(picture.rgb(5, 5)).as("sky").isEqualTo(50 << 16 | 100 << 8 | 210);
        int checked = 0;
        for (int x = 10; x < 960; x += 37) {
            // the bottom row sees the floor's top, y = 0, in no shadow; the tiles are 1.2 wide, the checker's
            // rule floor(x/1.2) + floor(y) + floor(z/1.2) with y just below 0 (floor −1): an even sum of x's and
            // z's floors is odd in all, so yellow (b); an odd one red (a)
            Ray ray = scene.camera().generateRay(x, 535, 960, 540);
            float t = -ray.origin().y() / ray.direction().y();
            Vector3f p = ray.pointAt(t);
            double u = p.x() / 1.2;
            double w = p.z() / 1.2;
            if (Math.abs(u - Math.rint(u)) < 0.02 || Math.abs(w - Math.rint(w)) < 0.02) {
                continue; // too near a tile's edge to tell by hand
            }
            boolean yellow = (Math.floor(u) + Math.floor(w)) % 2 == 0;
            int green = picture.rgb(x, 535) >> 8 & 0xFF;
            int red = picture.rgb(x, 535) >> 16 & 0xFF;
            assertThat(red).as("red at x = %d", x).isGreaterThan(150);
            if (yellow) {
                assertThat(green).as("a yellow tile at x = %d", x).isGreaterThan(150);
            } else {
                assertThat(green).as("a red tile at x = %d", x).isLessThan(60);
            }
            checked++;
        }
        assertThat(checked).isGreaterThan(15);
    }

    @Test
    void theEllipsoidIsTheSphereStretchedAndTheBoxIsTippedOntoItsEdge() {
        Scene scene = Scenes.example("ellipsoid_and_tilted_box");
        IGeometry egg = scene.objects().get(1);
        IGeometry box = scene.objects().get(2);
        // the egg: the unit sphere scaled 2|1|1, turned about z (which leaves z alone), moved to (-2|1.6|0):
        // a ray along -z through its centre meets it at z = 1, so from z = 10 at t = 9
        assertThat(egg.intersect(new Ray(new Vector3f(-2, 1.6f, 10), new Vector3f(0, 0, -1))).t())
                .isCloseTo(9f, within(1e-5f));
        // its long axis, stretched to 2, is turned 30° from x: along it the surface lies 2 from the centre
        Vector3f along = new Vector3f((float) Math.cos(Math.toRadians(30)), (float) Math.sin(Math.toRadians(30)), 0);
        Vector3f from = new Vector3f(-2, 1.6f, 0).add(along.multiply(10));
        assertThat(egg.intersect(new Ray(from, along.inverse())).t()).isCloseTo(10 - 2f, within(1e-5f));
        // the cube turned 45° about y points an edge at +z, at z = √2; tipped 20° about x, the edge's point
        // at y = √2·tan 20° = 0.51473 comes to height 0 and to z = 0.51473·sin 20° + √2·cos 20° = 1.50500
        assertThat(box.intersect(new Ray(new Vector3f(2.2f, 1.2f, 10), new Vector3f(0, 0, -1))).t())
                .isCloseTo(10 - 1.50500f, within(1e-4f));
    }
}
