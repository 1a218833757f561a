package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.charset.StandardCharsets;
import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.scene.Scene;
import rtd.testing.RandomScenes;

/** Reading a large file in parts, in parallel, gives what reading it in one go gives. */
@DisplayName("Reading a scene file in parts")
class PartsTest {

    private static final String[] MISTAKES = {"spere:(1|2|3):(1):(0|0|0)", "sphere:(1|2):(1):(0|0|0)",
        "orthographic_camera:(0|0|20):(0|0|-1):(50)", "ambient:(1|2|3)", "sphere:(1|2|3):(-1):(0|0|0)", "x",
        "7 sphere:(1|2|3):(1):(0|0|0)", "/* a comment\nof two lines */", "# a comment", "sphere:(1|2|3):(1,5):(0|0|0)"};

    @ParameterizedTest(name = "a valid scene, seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void givesTheSameSceneForAnyCut(long seed) throws SceneException {
        byte[] text = SceneRoundTripTest.write(RandomScenes.generate(seed, 300), new Random(seed)).getBytes(StandardCharsets.UTF_8);
        SourceText source = new SourceText("scene.txt", text);
        Scene whole = SceneParser.parse(source, Integer.MAX_VALUE);
        for (int partSize : new int[] {1, 50, 333, 4096}) {
            Scene parts = SceneParser.parse(source, partSize);
            assertThat(parts.objects()).isEqualTo(whole.objects());
            assertThat(parts.ambient()).isEqualTo(whole.ambient());
        }
    }

    @ParameterizedTest(name = "a scene with mistakes, seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5})
    void givesTheSameMistakesForAnyCut(long seed) {
        Random random = new Random(seed);
        String valid = SceneRoundTripTest.write(RandomScenes.generate(seed, 200), random);
        StringBuilder text = new StringBuilder();
        for (String line : valid.split("\n", -1)) {
            text.append(random.nextInt(12) == 0 ? MISTAKES[random.nextInt(MISTAKES.length)] + "\n" : "").append(line).append('\n');
        }
        String lineEnds = seed % 2 == 0 ? text.toString() : text.toString().replace('\n', '\r'); // old Mac files too
        SourceText source = new SourceText("scene.txt", lineEnds.getBytes(StandardCharsets.UTF_8));
        String whole = catchThrowableOfType(SceneException.class, () -> SceneParser.parse(source, Integer.MAX_VALUE)).report();
        for (int partSize : new int[] {1, 64, 700, 5000}) {
            assertThat(catchThrowableOfType(SceneException.class, () -> SceneParser.parse(source, partSize)).report())
                    .isEqualTo(whole);
        }
    }
}
