package rtd.explain;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.io.SceneException;
import rtd.io.SceneIO;
import rtd.scene.Scene;

@DisplayName("Explaining a pixel of a transformed or patterned object")
class PatternsAndTransformsExplainedTest {

    private static Scene scene(String... lines) throws SceneException {
        return SceneIO.parseScene("scene.txt", String.join("\n", lines) + "\n");
    }

    @Test
    void aStretchedSphereShowsItsMatrixTheRayInItsSpaceAndTheSpheresOwnQuadratic() throws SceneException {
        // pixel (11, 10) of 20 × 20 at zoom 1: O = (1|0|20), R = (0|0|-1). M = scale 2|1|1, so M⁻¹O = (0.5|0|20)
        // and M⁻¹R = R: a = 1, b = 2·(-1)·20 = -40, c = 0.25 + 400 - 1 = 399.25, b² - 4ac = 1600 - 1597 = 3
        Scene scene = scene("orthographic_camera:(0|0|20):(0|0|-1):(1)", "transform:(wide):(scale 2|1|1)",
                "sphere:(0|0|0):(1):(255|0|0):(wide)");
        String text = PixelExplanation.of(scene, 11, 10, 20, 20);
        assertThat(text).contains("#1 sphere, transformed by M = [2 0 0 0; 0 1 0 0; 0 0 1 0; 0 0 0 1]",
                "the ray in the shape's own space: M⁻¹O = (0.5|0|20), M⁻¹R = (0|0|-1)", "a = R·R = 1",
                "b = 2·R·(O − M) = -40", "c = (O − M)·(O − M) − r² = 399.25", "discriminant b² − 4ac = 3 ≥ 0",
                "P = O + t·R on the world's ray, at the same t", "pixel colour: 255 0 0");
        assertThat(text.indexOf("M⁻¹O")).isLessThan(text.indexOf("a = R·R"));
    }

    @Test
    void aCheckerFloorSaysWhichRuleChoseTheColour() throws SceneException {
        // pixel (17, 7) of 20 × 20 at zoom 2: O = (3.5|1.5|20); the floor z = 0 is hit at (3.5|1.5|0), and
        // under = P − ε·N lies at z = −1e-4·(1 + 3.5) = −0.00045: floor 3 + 1 + (−1) = 3, odd, so b
        Scene scene = scene("orthographic_camera:(0|0|20):(0|0|-1):(2)",
                "pattern:(checks):(checker):(255|0|0):(0|0|255)", "plane:(0|0|0):(0|0|1):(checks)");
        String text = PixelExplanation.of(scene, 17, 7, 20, 20);
        assertThat(text).contains("#1 plane, patterned: its colour at under = P − ε·N = (3.5|1.5|-0.00045)",
                "checker pattern, a = (255|0|0), b = (0|0|255), at (3.5|1.5|-0.00045) in its space",
                "floor(x) + floor(y) + floor(z) = 3: odd, so b = (0|0|255)", "pixel colour: 0 0 255");
    }

    @Test
    void aShadedStripedSphereSaysItsColourComesFromItsPattern() throws SceneException {
        // pixel (10, 10): O = (0|0|20), hits the sphere of radius 1 at (0|0|1); under is (0|0|1 − 2e-4): floor(0) = 0,
        // even, so a, the pattern scaled by 0.5 changes nothing at x = 0
        Scene scene = scene("orthographic_camera:(0|0|20):(0|0|-1):(1)", "transform:(thin):(scale 0.5)",
                "pattern:(bands):(stripes):(255|255|255):(0|0|0):(thin)", "sphere:(0|0|0):(1):(bands)",
                "light:(0|0|10):(255|255|255)");
        String text = PixelExplanation.of(scene, 10, 10, 20, 20);
        assertThat(text).contains("colour from its pattern, at under = P − ε·N", "stripes pattern, a = (255|255|255)",
                "floor(x) = 0: even, so a = (255|255|255)");
    }

    @Test
    void aMovedCylinderShowsItsOwnSideTestInItsSpace() throws SceneException {
        // pixel (12, 10) of 20 × 20 at zoom 1: O = (2|0|20), R = (0|0|-1); translate 2|0|0 gives M⁻¹O = (0|0|20).
        // The axis is y from A = (0|-1|0), its middle (0|0|0): t0 = 20, O' = (0|0|0), w = (0|1|0), h = (0|1|0):
        // a = 1 − 0 = 1, b = 2·(0 − 1·0) = 0, c = 1 − 1 − 1 = -1, b² − 4ac = 4, t = 20 ± 1
        Scene scene = scene("orthographic_camera:(0|0|20):(0|0|-1):(1)", "transform:(right):(translate 2|0|0)",
                "cylinder:(0|-1|0):(0|1|0):(1):(255|0|0):(right)");
        String text = PixelExplanation.of(scene, 12, 10, 20, 20);
        assertThat(text).contains("#1 cylinder, transformed by M = [1 0 0 2; 0 1 0 0; 0 0 1 0; 0 0 0 1]",
                "M⁻¹O = (0|0|20)", "t0 = (M − O)·R/(R·R) = 20", "a = R·R − (h·R)² = 1", "c = w·w − (h·w)² − r² = -1",
                "discriminant b² − 4ac = 4 ≥ 0", "root t = t0 + t' = 19", "root t = t0 + t' = 21",
                "nearest: t = 19 on the side: a hit", "P = O + t·R on the world's ray, at the same t = 19");
    }
}
