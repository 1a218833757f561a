package rtd.window;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.image.Picture;

@DisplayName("The progressive buffer: coarse blocks, refined")
class ProgressiveBufferTest {

    @Test
    void aStillPictureIsRefinedInBlocksOfEightFourTwoAndOne() {
        assertThat(Refinement.STILL.blocks()).containsExactly(8, 4, 2, 1);
        assertThat(Refinement.MOVING.blocks()).containsExactly(2);
        assertThat(Refinement.RESTED.blocks()).containsExactly(1);
        assertThat(Refinement.MOVING.endsFull()).isFalse();
        assertThat(Refinement.STILL.endsFull()).isTrue();
    }

    @Test
    void aSceneTooSlowForMovingFramesOfBlocksOf2TakesCoarserBlocks() {
        long frame = Refinement.FRAME_NANOS;
        assertThat(Refinement.moving(2, 0).blocks()).containsExactly(2); // the first moving frame
        assertThat(Refinement.moving(2, frame).blocks()).containsExactly(2);
        // twice too slow at blocks of 2: blocks of 4 take a quarter of the rays
        assertThat(Refinement.moving(2, 2 * frame).blocks()).containsExactly(4);
        // a frame of blocks of 4 in a third of the time: blocks of 2 would take 4/3 of it, too long; stay at 4
        assertThat(Refinement.moving(4, frame / 3).blocks()).containsExactly(4);
        assertThat(Refinement.moving(4, frame / 5).blocks()).containsExactly(2);
        assertThat(Refinement.moving(2, 100 * frame).blocks()).containsExactly(8);
    }

    @Test
    void theBlocksCoverThePictureTheLastOneCutOff() {
        // 5 pixels in blocks of 2: [0, 2), [2, 4), [4, 5)
        assertThat(ProgressiveBuffer.blocks(5, 2)).isEqualTo(3);
        assertThat(ProgressiveBuffer.blocks(960, 8)).isEqualTo(120);
        assertThat(ProgressiveBuffer.blocks(90, 8)).isEqualTo(12);
    }

    @Test
    void eachBlockTakesItsOnePixelsColour() {
        ProgressiveBuffer buffer = new ProgressiveBuffer(5, 3);
        // 3 × 2 coarse pixels for blocks of 2: a, b, c on top, d, e, f below
        buffer.put(2, new Picture(3, 2, new int[] {0xA, 0xB, 0xC, 0xD, 0xE, 0xF}));
        assertThat(buffer.picture().rgb()).containsExactly(
                0xA, 0xA, 0xB, 0xB, 0xC,
                0xA, 0xA, 0xB, 0xB, 0xC,
                0xD, 0xD, 0xE, 0xE, 0xF);
    }

    @Test
    void theLastPassSetsEveryPixelItself() {
        ProgressiveBuffer buffer = new ProgressiveBuffer(2, 2);
        buffer.put(8, new Picture(1, 1, new int[] {7}));
        buffer.put(1, new Picture(2, 2, new int[] {1, 2, 3, 4}));
        assertThat(buffer.picture().rgb()).containsExactly(1, 2, 3, 4);
    }

    @Test
    void aPassOfTheWrongSizeIsRefused() {
        ProgressiveBuffer buffer = new ProgressiveBuffer(5, 3);
        assertThatThrownBy(() -> buffer.put(2, new Picture(2, 2, new int[4])))
                .hasMessageContaining("has 3 × 2 pixels, not 2 × 2");
    }
}
