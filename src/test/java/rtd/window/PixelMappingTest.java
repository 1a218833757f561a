package rtd.window;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.window.PicturePanel.PixelMapping;

@DisplayName("The mapping from the window's panel to the picture's pixels")
class PixelMappingTest {

    @Test
    void aPanelOfThePicturesSizeShowsEachPixelAtItsPlace() {
        PixelMapping same = PixelMapping.of(160, 90, 160, 90);
        assertThat(same.pixelAt(0, 0)).containsExactly(0, 0);
        assertThat(same.pixelAt(12.7, 40.2)).containsExactly(12, 40);
        assertThat(same.pixelAt(159.9, 89.9)).containsExactly(159, 89);
        assertThat(same.pixelAt(160, 10)).isNull();
    }

    @Test
    void aLargerPanelScalesThePictureToFitAndCentresIt() {
        // 320 × 200 holds 160 × 90 twice as large, 320 × 180, with (200 − 180) / 2 = 10 rows above and below
        PixelMapping larger = PixelMapping.of(160, 90, 320, 200);
        assertThat(larger.scale()).isEqualTo(2.0);
        assertThat(larger.left()).isEqualTo(0.0);
        assertThat(larger.top()).isEqualTo(10.0);
        assertThat(larger.pixelAt(5, 5)).isNull();
        assertThat(larger.pixelAt(0, 10)).containsExactly(0, 0);
        assertThat(larger.pixelAt(3, 13)).containsExactly(1, 1);
        assertThat(larger.pixelAt(319.9, 189.9)).containsExactly(159, 89);
        assertThat(larger.pixelAt(100, 190)).isNull();
    }

    @Test
    void aSmallerPanelShrinksThePictureAndMapsBack() {
        // 80 × 60 holds 160 × 90 at half size, 80 × 45, with 7.5 rows above
        PixelMapping smaller = PixelMapping.of(160, 90, 80, 60);
        assertThat(smaller.scale()).isEqualTo(0.5);
        assertThat(smaller.pixelAt(10, 7.5 + 10)).containsExactly(20, 20);
        assertThat(smaller.panelX(20)).isEqualTo(10.0);
        assertThat(smaller.panelY(20)).isEqualTo(17.5);
    }
}
