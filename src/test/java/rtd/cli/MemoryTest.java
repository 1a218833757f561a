package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

@DisplayName("Messages about memory")
class MemoryTest {

    private static final long MIB = 1L << 20;
    private static final long GIB = 1L << 30;

    @Test
    void amountsUseAUnitThatShowsTheDifferenceBetweenSmallOnes() {
        assertThat(Memory.size(1920L * 1080 * 10)).isEqualTo("19.8 MiB");
        assertThat(Memory.size(16 * MIB)).isEqualTo("16.0 MiB");
        assertThat(Memory.size(512 * 1024)).isEqualTo("512.0 KiB");
        assertThat(Memory.size(46000L * 46000 * 10)).isEqualTo("19.7 GiB");
    }

    @Test
    void theOutOfMemoryHintNeverAdvisesMoreMemoryThanTheMachineHas() {
        Pattern xmx = Pattern.compile("-Xmx(\\d+)([mg])");
        long[] heaps = {16 * MIB, 256 * MIB, GIB, 3 * GIB, 6 * GIB, 15 * GIB};
        long[] machines = {GIB, 4 * GIB, 8 * GIB, 16 * GIB, 23 * GIB + 500 * MIB, 64 * GIB};
        for (long heap : heaps) {
            for (long machine : machines) {
                String message = Memory.outOfMemory(heap, machine);
                Matcher advice = xmx.matcher(message);
                if (advice.find()) {
                    long advised = Long.parseLong(advice.group(1)) * (advice.group(2).equals("g") ? GIB : MIB);
                    assertThat(advised).as(message).isLessThanOrEqualTo(machine).isGreaterThan(heap);
                } else {
                    assertThat(message).as("heap %d, machine %d", heap, machine).contains("this machine has");
                }
            }
        }
        assertThat(Memory.outOfMemory(3 * GIB, 4 * GIB)).isEqualTo("rtd: out of memory: Java may use 3.0 GiB here, "
                + "and this machine has 4.0 GiB in all; render a smaller image (--width/--height) or a scene with fewer objects");
        assertThat(Memory.outOfMemory(16 * MIB, 4 * GIB)).isEqualTo("rtd: out of memory: Java may use only 16.0 MiB here; "
                + "give it more, for example: java -Xmx64m -jar rtd.jar ...");
    }

    @Test
    void imageSizeAdviceOnTheLimitIsForAmountsTheMachineHas() {
        assertThat(Memory.xmx(25 * MIB, 4 * GIB)).contains("64m");
        assertThat(Memory.xmx(22 * GIB + 700 * MIB, 64 * GIB)).contains("23g");
        assertThat(Memory.xmx(22 * GIB + 700 * MIB, 16 * GIB)).isEmpty();
    }
}
