package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
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

    /**
     * Objects that name a material defined above them in their part are built as they are read,
     * the others when the parts are joined: either way the same scene and the same warnings.
     */
    @ParameterizedTest(name = "cut every {0} bytes")
    @ValueSource(ints = {1, 40, 200, 100_000})
    void givesTheSameObjectsAndWarningsWhereverTheirMaterialsAreDefined(int partSize) throws SceneException {
        SourceText source = new SourceText("scene.txt", String.join("\n",
                "orthographic_camera:(0|0|20):(0|0|-1):(50)",
                "sphere:(0|0|0):(1):(255|0|0):(below)",
                "material:(above):(reflective=0.5)",
                "sphere:(1|0|0):(1):(255|0|0):(above)",
                "material:(below):(specular=0.1)",
                "material:(unused):(diffuse=0.5)",
                "triangle:(0|0|0):(1|0|0):(0|1|0):(0|255|0):(above)",
                "sphere:(2|0|0):(1):(0|0|255):(below)").getBytes(StandardCharsets.UTF_8));
        List<SceneError> wholeWarnings = new ArrayList<>();
        Scene whole = SceneParser.parse(source, Integer.MAX_VALUE, wholeWarnings);
        List<SceneError> warnings = new ArrayList<>();

        Scene parts = SceneParser.parse(source, partSize, warnings);

        assertThat(parts.objects()).extracting(PartsTest::described)
                .isEqualTo(whole.objects().stream().map(PartsTest::described).toList());
        assertThat(parts.objects()).extracting(object -> object.material().reflective())
                .containsExactly(0f, 0.5f, 0.5f, 0f);
        assertThat(parts.objects()).extracting(object -> object.material().specular())
                .containsExactly(0.1f, Material.DEFAULT.specular(), Material.DEFAULT.specular(), 0.1f);
        assertThat(warnings).isEqualTo(wholeWarnings);
        assertThat(warnings).extracting(SceneError::message).anySatisfy(message -> assertThat(message).contains("unused"))
                .noneSatisfy(message -> assertThat(message).contains("'above'"));
    }

    /** What an object is, by value: its kind, its box, its colour and finish. */
    private static String described(IGeometry object) {
        return object.kind() + " " + object.bounds() + " " + object.color() + " " + object.material();
    }

    /** A material defined twice: the second is a mistake, and an object after both gets the first. */
    @ParameterizedTest(name = "cut every {0} bytes")
    @ValueSource(ints = {1, 40, 100_000})
    void givesTheSameMistakesWhereAMaterialIsDefinedTwice(int partSize) {
        SourceText source = new SourceText("scene.txt", String.join("\n",
                "orthographic_camera:(0|0|20):(0|0|-1):(50)",
                "material:(m):(reflective=0.5)",
                "material:(m):(reflective=0.25)",
                "sphere:(1|0|0):(-1):(255|0|0):(m)",
                "sphere:(1|0|0):(1):(255|0|0):(n)").getBytes(StandardCharsets.UTF_8));
        String whole = catchThrowableOfType(SceneException.class, () -> SceneParser.parse(source, Integer.MAX_VALUE)).report();

        assertThat(catchThrowableOfType(SceneException.class, () -> SceneParser.parse(source, partSize)).report())
                .isEqualTo(whole)
                .contains("a second material 'm'", "greater than 0", "unknown material 'n'");
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
