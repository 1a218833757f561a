package rtd.shade;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.geometry.Material;
import rtd.image.Rgb;
import rtd.math.Vector3f;
import rtd.scene.Light;

/** The Phong model of one light, with the well-known cases of The Ray Tracer Challenge worked out by hand. */
@DisplayName("The light a point light gives a point")
class LightingTest {

    private static final Rgb WHITE = new Rgb(1, 1, 1);
    private static final Vector3f POINT = Vector3f.ZERO;
    private static final Vector3f NORMAL = new Vector3f(0, 0, -1);
    private static final float HALF_ROOT_2 = (float) Math.sqrt(2) / 2;

    private static float light(Vector3f eye, Vector3f lightAt, boolean shadow) {
        Rgb result = Lighting.of(Material.DEFAULT, WHITE, new Light(lightAt, WHITE), POINT, eye, NORMAL, shadow);
        assertThat(result.green()).isEqualTo(result.red());
        assertThat(result.blue()).isEqualTo(result.red());
        return result.red();
    }

    @Test
    void withTheEyeBetweenTheLightAndTheSurfaceAllThreeTermsAddUp() {
        // ambient 0.1 + diffuse 0.9 · 1 + specular 0.9 · 1^200
        assertThat(light(new Vector3f(0, 0, -1), new Vector3f(0, 0, -10), false)).isCloseTo(1.9f, within(1e-5f));
    }

    @Test
    void withTheEyeOffset45DegreesTheHighlightIsGone() {
        // (Rl·E)^200 = (√2/2)^200 ≈ 1e-30: ambient 0.1 + diffuse 0.9
        assertThat(light(new Vector3f(0, HALF_ROOT_2, -HALF_ROOT_2), new Vector3f(0, 0, -10), false))
                .isCloseTo(1.0f, within(1e-5f));
    }

    @Test
    void withTheLightOffset45DegreesTheDiffuseTermShrinks() {
        // 0.1 + 0.9 · √2/2 = 0.7364
        assertThat(light(new Vector3f(0, 0, -1), new Vector3f(0, 10, -10), false)).isCloseTo(0.7364f, within(1e-4f));
    }

    @Test
    void withTheEyeInThePathOfTheReflectionTheHighlightIsFull() {
        // 0.1 + 0.9 · √2/2 + 0.9 = 1.6364
        assertThat(light(new Vector3f(0, -HALF_ROOT_2, -HALF_ROOT_2), new Vector3f(0, 10, -10), false))
                .isCloseTo(1.6364f, within(1e-4f));
    }

    @Test
    void aLightBehindTheSurfaceGivesOnlyTheAmbientTerm() {
        assertThat(light(new Vector3f(0, 0, -1), new Vector3f(0, 0, 10), false)).isCloseTo(0.1f, within(1e-6f));
    }

    @Test
    void aPointInShadowGetsOnlyTheAmbientTerm() {
        assertThat(light(new Vector3f(0, 0, -1), new Vector3f(0, 0, -10), true)).isCloseTo(0.1f, within(1e-6f));
    }

    @Test
    void theSurfaceColourAndTheLightColourMultiplyChannelByChannel() {
        Rgb lit = Lighting.of(Material.DEFAULT, new Rgb(1, 0.5f, 0), new Light(new Vector3f(0, 0, -10), new Rgb(1, 1, 0.5f)),
                POINT, new Vector3f(0, 0, -1), NORMAL, false);
        // (0.1 + 0.9) · c ⊙ I + 0.9 · I
        assertThat(lit.red()).isCloseTo(1.9f, within(1e-5f));
        assertThat(lit.green()).isCloseTo(0.5f + 0.9f, within(1e-5f));
        assertThat(lit.blue()).isCloseTo(0.45f, within(1e-5f));
    }

    @Test
    void aLightAtThePointItselfGivesItsAmbientPartAndNoNotANumber() {
        Rgb lit = Lighting.of(Material.DEFAULT, WHITE, new Light(POINT, WHITE), POINT, new Vector3f(0, 0, -1), NORMAL, false);
        assertThat(lit).isEqualTo(new Rgb(0.1f, 0.1f, 0.1f));
    }
}
