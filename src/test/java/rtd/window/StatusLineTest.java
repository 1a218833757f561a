package rtd.window;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

@DisplayName("The window's status line")
class StatusLineTest {

    @Test
    void itGivesTheFramesTimeRaysPerSecondSizeAndThePixelUnderTheMouse() {
        // 2,000,000 rays in 0.25 s: 8 Mrays/s
        assertThat(pass(250_000_000L, 2_000_000L, 1).status(960, 540, new int[] {12, 40}, "picture"))
                .isEqualTo("picture · 960 × 540 · last frame 0.250 s · 8.00 Mrays/s · pixel (12, 40)");
    }

    @Test
    void aCoarseFrameSaysItsBlocksAndNoPixelWhenTheMouseIsOutside() {
        assertThat(pass(100_000_000L, 129_600L, 2).status(960, 540, null, "cost"))
                .isEqualTo("cost · 960 × 540 (blocks of 2 × 2) · last frame 0.100 s · 1.30 Mrays/s");
    }

    @Test
    void theClockIsWrittenWithThreeDecimals() {
        assertThat(WindowSession.label(0.25)).isEqualTo("clock 0.250");
        assertThat(WindowSession.label(1.0 / 3)).isEqualTo("clock 0.333");
    }

    private static FrameRenderer.Pass pass(long nanos, long rays, int block) {
        return new FrameRenderer.Pass(null, block, nanos, rays, "");
    }
}
