package rtd.explain;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.io.SceneException;
import rtd.io.SceneIO;
import rtd.scene.Scene;

/** {@code --explain} of a cylinder's and a cone's test, and of an area light's samples, in the kernel's and the shader's own numbers. */
@DisplayName("The explanation of cylinders, cones and area lights")
class SolidsAndSoftShadowsExplainedTest {

    /**
     * Pixel (1010, 540): O = (1|0|20), R = (0|0|−1). The axis's middle is (0|0|0), t0 = 20,
     * w = (1|2|0): a = 1, b = 0, c = 5 − 4 − 4 = −3, b² − 4ac = 12, t = 20 ∓ √3.
     */
    @Test
    void aCylindersQuadraticAndCapsAreShownAsItsTestComputesThem() throws SceneException {
        Scene scene = SceneIO.parseScene("c.txt", "orthographic_camera:(0|0|20):(0|0|-1):(50)\n"
                + "cylinder:(0|-2|0):(0|2|0):(2):(200|60|40)\n");
        String text = PixelExplanation.of(scene, 1010, 540, 1920, 1080);
        assertThat(text).contains("t0 = (M − O)·R/(R·R) = 20", "a = R·R − (h·R)² = 1", "b = 2·(w·R − (h·w)(h·R)) = 0",
                "c = w·w − (h·w)² − r² = -3", "discriminant b² − 4ac = 12 ≥ 0",
                "root t = t0 + t' = 18.26795: s = h·(P − A) = 2, between the ends",
                "first cap (at A): the ray runs parallel to its plane", "nearest: t = 18.26795 on the side: a hit");
    }

    /** Down the axis of a cone with its apex up: its side's slope k = −0.5, and the apex, a cap of radius 0, is hit at t = 3. */
    @Test
    void aConesApexIsACapOfRadius0() throws SceneException {
        Scene scene = SceneIO.parseScene("c.txt", "orthographic_camera:(0|5|0):(0|-1|0):(50)\n"
                + "cone:(0|0|0):(1):(0|2|0):(0):(60|160|220)\n");
        String text = PixelExplanation.of(scene, 2, 2, 4, 4);
        assertThat(text).contains("cone: A = (0|0|0), r1 = 1, B = (0|2|0), r2 = 0", "a = R·R − (1 + k²)(h·R)² = -0.25",
                "second cap (at B): its plane at t = 3, |P − B|² = 0 ≤ r² = 0: on the cap", "nearest: t = 3 on the side: a hit");
    }

    /** The line light of 2 × 1 samples and the box over one of them (the walkthrough's): 1 of 2 lit, 164. */
    @Test
    void anAreaLightsSamplesAreShownWithHowManyAreLit() throws SceneException {
        Scene scene = SceneIO.parseScene("s.txt", "orthographic_camera:(0|10|0):(0|-1|0):(10)\n"
                + "area_light:(-1|4|0):(2|0|0):(0|0|0):(2|1):(255|255|255)\nplane:(0|0|0):(0|1|0):(255|255|255)\n"
                + "box:(0.1|2|-0.2):(0.5|2.2|0.2):(255|255|255)\n");
        String text = PixelExplanation.of(scene, 10, 10, 20, 20);
        assertThat(text).contains("1 light (2 point lights: each area light is its samples)",
                "light 1, an area light: corner (-1|4|0), edges u = (2|0|0), v = (0|0|0), 2 × 1 samples",
                "sample (0, 0) at (-0.5|4|0): lit", "sample (1, 0) at (0.5|4|0): in shadow of #2 box",
                "1 of 2 samples lit; the area light gives (0.6419893|0.6419893|0.6419893)", "164 164 164");
    }
}
