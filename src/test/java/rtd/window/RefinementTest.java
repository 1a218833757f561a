package rtd.window;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.image.Picture;

@DisplayName("The window's passes: coarse blocks, refined")
class RefinementTest {

    @Test
    void aStillPictureIsRefinedInBlocksOfEightFourTwoAndOne() {
        assertThat(FrameRenderer.STILL).containsExactly(8, 4, 2, 1);
        assertThat(FrameRenderer.MOVING).containsExactly(2);
        assertThat(FrameRenderer.RESTED).containsExactly(1);
    }

    @Test
    void aSceneTooSlowForMovingFramesOfBlocksOf2TakesCoarserBlocks() {
        long frame = FrameRenderer.FRAME_NANOS;
        assertThat(FrameRenderer.moving(2, 0)).containsExactly(2); // the first moving frame
        assertThat(FrameRenderer.moving(2, frame)).containsExactly(2);
        // twice too slow at blocks of 2: blocks of 4 take a quarter of the rays
        assertThat(FrameRenderer.moving(2, 2 * frame)).containsExactly(4);
        // a frame of blocks of 4 in a third of the time: blocks of 2 would take 4/3 of it, too long; stay at 4
        assertThat(FrameRenderer.moving(4, frame / 3)).containsExactly(4);
        assertThat(FrameRenderer.moving(4, frame / 5)).containsExactly(2);
        assertThat(FrameRenderer.moving(2, 100 * frame)).containsExactly(8);
    }

    @Test
    void theBlocksCoverThePictureTheLastOneCutOff() {
        // 5 pixels in blocks of 2: [0, 2), [2, 4), [4, 5)
        assertThat(FrameRenderer.blocks(5, 2)).isEqualTo(3);
        assertThat(FrameRenderer.blocks(960, 8)).isEqualTo(120);
        assertThat(FrameRenderer.blocks(90, 8)).isEqualTo(12);
    }

    @Test
    void eachBlockTakesItsOnePixelsColour() {
        // 3 × 2 coarse pixels for blocks of 2: a, b, c on top, d, e, f below
        Picture coarse = new Picture(3, 2, new int[] {0xA, 0xB, 0xC, 0xD, 0xE, 0xF});
        assertThat(FrameRenderer.filled(2, coarse, 5, 3).rgb()).containsExactly(
                0xA, 0xA, 0xB, 0xB, 0xC,
                0xA, 0xA, 0xB, 0xB, 0xC,
                0xD, 0xD, 0xE, 0xE, 0xF);
    }

    @Test
    void theLastPassSetsEveryPixelItself() {
        assertThat(FrameRenderer.filled(1, new Picture(2, 2, new int[] {1, 2, 3, 4}), 2, 2).rgb())
                .containsExactly(1, 2, 3, 4);
    }
}
