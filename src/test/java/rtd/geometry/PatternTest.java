package rtd.geometry;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.image.Color;
import rtd.math.Matrix4;
import rtd.math.Ray;
import rtd.math.Vector3f;

@DisplayName("Patterns (The Ray Tracer Challenge, chapter 10)")
class PatternTest {

    private static final Color A = new Color(255, 255, 255);
    private static final Color B = new Color(0, 0, 0);

    private static Pattern pattern(Pattern.Kind kind) {
        return new Pattern(kind, A, B, Matrix4.IDENTITY);
    }

    private static Color at(Pattern p, float x, float y, float z) {
        return p.colourAt(new Vector3f(x, y, z));
    }

    @Test
    void stripesAlternateWithFloorOfX() {
        Pattern stripes = pattern(Pattern.Kind.STRIPES);
        assertThat(at(stripes, 0, 0, 0)).isEqualTo(A);
        assertThat(at(stripes, 0.9f, 5, -7)).isEqualTo(A);   // floor(0.9) = 0: even
        assertThat(at(stripes, 1, 0, 0)).isEqualTo(B);       // 1: odd
        assertThat(at(stripes, -0.1f, 0, 0)).isEqualTo(B);   // floor(-0.1) = -1: odd
        assertThat(at(stripes, -1.1f, 0, 0)).isEqualTo(A);   // -2: even
    }

    @Test
    void aGradientBlendsLinearlyAndRoundsHalfUp() {
        Pattern gradient = pattern(Pattern.Kind.GRADIENT);
        assertThat(at(gradient, 0, 0, 0)).isEqualTo(A);
        // 255 + (0 - 255)·0.25 = 191.25 -> 191; ·0.5 = 127.5 -> 128 (½ up); ·0.75 = 63.75 -> 64
        assertThat(at(gradient, 0.25f, 0, 0)).isEqualTo(new Color(191, 191, 191));
        assertThat(at(gradient, 0.5f, 0, 0)).isEqualTo(new Color(128, 128, 128));
        assertThat(at(gradient, 1.75f, 0, 0)).isEqualTo(new Color(64, 64, 64));
    }

    @Test
    void ringsAlternateWithTheDistanceFromTheYAxis() {
        Pattern rings = pattern(Pattern.Kind.RINGS);
        assertThat(at(rings, 0, 0, 0)).isEqualTo(A);
        assertThat(at(rings, 1, 0, 0)).isEqualTo(B);
        assertThat(at(rings, 0, 0, 1)).isEqualTo(B);
        assertThat(at(rings, 0.708f, 0, 0.708f)).isEqualTo(B); // √(2·0.708²) = 1.0013: floor 1
        assertThat(at(rings, 1.5f, 9, 1.5f)).isEqualTo(A);     // √4.5 = 2.12: floor 2, y does not count
    }

    @Test
    void aCheckerAddsTheFloorsOfAllThree() {
        Pattern checker = pattern(Pattern.Kind.CHECKER);
        assertThat(at(checker, 0.5f, 0.5f, 0.5f)).isEqualTo(A);
        assertThat(at(checker, 1.5f, 0.5f, 0.5f)).isEqualTo(B);
        assertThat(at(checker, 1.5f, 1.5f, 0.5f)).isEqualTo(A);
        assertThat(at(checker, 1.5f, 1.5f, 1.5f)).isEqualTo(B); // 1 + 1 + 1 = 3: odd
        assertThat(at(checker, -0.5f, 0.5f, 0.5f)).isEqualTo(B);
    }

    @Test
    void thePatternsOwnTransformPlacesIt() {
        // stripes scaled by 2: x = 1.5 is 0.75 in the pattern's space, floor 0: a
        Pattern wide = new Pattern(Pattern.Kind.STRIPES, A, B, Matrix4.scale(2, 2, 2));
        assertThat(at(wide, 1.5f, 0, 0)).isEqualTo(A);
        assertThat(at(wide, 2.5f, 0, 0)).isEqualTo(B);
    }

    @Test
    void aCheckerFloorAtYZeroShowsOneColourPerTileFromAboveAndBelow() {
        // the floor lies on the boundary y = 0; the colour is taken at P - ε·N, just under the surface
        Plane floor = new Plane(new Vector3f(0, 0, 0), new Vector3f(0, 1, 0), Color.BLACK, Material.DEFAULT);
        Patterned tiles = new Patterned(floor, pattern(Pattern.Kind.CHECKER));
        for (float x = 0.05f; x < 1; x += 0.1f) {
            for (float z = 0.05f; z < 1; z += 0.1f) {
                // the tile 0 < x, z < 1: from above, under has y < 0, floor(y) = -1: odd, b
                assertThat(colourSeen(tiles, x, 5, z, 0, -1, 0)).isEqualTo(B);
                assertThat(colourSeen(tiles, x + 1, 5, z, 0, -1, 0)).isEqualTo(A);
                // from below, under lies above the floor: y > 0, so the tile shows a
                assertThat(colourSeen(tiles, x, -5, z, 0, 1, 0)).isEqualTo(A);
            }
        }
    }

    @Test
    void aTransformedObjectsPatternMovesWithIt() {
        // a sphere at the origin with stripes, moved by 1 in x: the world point (1.5|0|0) is (0.5|0|0) in its space
        Sphere ball = new Sphere(new Vector3f(0, 0, 0), 1, Color.BLACK);
        Transformed moved = new Transformed(new Patterned(ball, pattern(Pattern.Kind.STRIPES)), Matrix4.translate(1, 0, 0));
        assertThat(moved.isPatterned()).isTrue();
        assertThat(moved.colorAt(new Vector3f(1.5f, 0, 0))).isEqualTo(A);
        assertThat(moved.colorAt(new Vector3f(0.5f, 0, 0))).isEqualTo(B);
    }

    private static Color colourSeen(IGeometry object, float ox, float oy, float oz, float dx, float dy, float dz) {
        Ray ray = new Ray(new Vector3f(ox, oy, oz), new Vector3f(dx, dy, dz));
        Intersection i = object.intersect(ray);
        Hit hit = new Hit(object, 0, i.t(), 0, i.contactCoord());
        return hit.colour(ray.direction());
    }
}
