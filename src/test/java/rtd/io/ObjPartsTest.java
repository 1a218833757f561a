package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Reading a large OBJ file in parts, in parallel, gives what reading it in one go gives. */
@DisplayName("Reading an OBJ file in parts")
class ObjPartsTest {

    private static final int[] PART_SIZES = {1, 7, 40, 333, 4096};
    private static final String[] MISTAKES = {"v 1 2", "v 1 x 3", "vn 0 0", "f 1 2", "f 1 0 1", "f 1 2 999999", "f -999999 1 2",
        "f 1//9999 1//1 1//1", "f 1 a 2", "f 1/1/x 2 3", "v 1 NaN 2", "v 1e99 0 0", "f 1 2 3/", "f"};

    @ParameterizedTest(name = "a valid file, seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void givesTheSameMeshForAnyCut(long seed) throws SceneException {
        SourceText source = new SourceText("model.obj", obj(new Random(seed), 0).getBytes(StandardCharsets.UTF_8));
        ObjMesh whole = ObjParser.parse(source, Integer.MAX_VALUE);
        assertThat(whole.count()).isGreaterThan(100);
        for (int partSize : PART_SIZES) {
            ObjMesh parts = ObjParser.parse(source, partSize);
            assertThat(parts.count()).isEqualTo(whole.count());
            assertThat(parts.vertices()).isEqualTo(whole.vertices());
            assertThat(parts.normals()).isEqualTo(whole.normals());
            assertThat(Arrays.copyOf(parts.corners(), 3 * parts.count())).isEqualTo(Arrays.copyOf(whole.corners(), 3 * whole.count()));
            assertThat(Arrays.copyOf(parts.cornerNormals(), 3 * parts.count()))
                    .isEqualTo(Arrays.copyOf(whole.cornerNormals(), 3 * whole.count()));
        }
    }

    @ParameterizedTest(name = "a file with mistakes, seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void givesTheSameMistakesForAnyCut(long seed) {
        int oneLineIn = seed % 2 == 0 ? 15 : 60; // more mistakes than are reported, and fewer
        SourceText source = new SourceText("model.obj", obj(new Random(seed), oneLineIn).getBytes(StandardCharsets.UTF_8));
        String whole = catchThrowableOfType(SceneException.class, () -> ObjParser.parse(source, Integer.MAX_VALUE)).report();
        for (int partSize : PART_SIZES) {
            assertThat(catchThrowableOfType(SceneException.class, () -> ObjParser.parse(source, partSize)).report())
                    .isEqualTo(whole);
        }
    }

    /**
     * A random model: vertices, normals and faces mixed, in every corner form, with negative
     * indices, comments and lines that are skipped; one line in about {@code oneLineIn} is wrong
     * (none for 0). Some start with a byte-order mark; some files with mistakes end their lines
     * in CR LF.
     */
    private static String obj(Random random, int oneLineIn) {
        boolean mistakes = oneLineIn > 0;
        StringBuilder text = new StringBuilder(random.nextBoolean() ? "\uFEFF# a model\n" : "");
        int vertices = 0;
        int normals = 0;
        for (int line = 0; line < 600; line++) {
            int kind = random.nextInt(10);
            if (mistakes && random.nextInt(oneLineIn) == 0) {
                text.append(MISTAKES[random.nextInt(MISTAKES.length)]);
            } else if (kind < 3 || vertices < 3) {
                text.append(random.nextBoolean() ? "v " : "  v\t").append(number(random)).append(' ').append(number(random))
                        .append(' ').append(number(random)).append(random.nextInt(5) == 0 ? " 1.0 # w" : "");
                vertices++;
            } else if (kind == 3) {
                text.append("vn ").append(number(random)).append(' ').append(number(random)).append(' ').append(number(random));
                normals++;
            } else if (kind == 4) {
                text.append(random.nextBoolean() ? "# a comment" : random.nextBoolean() ? "vt 0.5 0.5" : "usemtl skin");
            } else {
                text.append('f');
                int corners = 3 + random.nextInt(3);
                for (int c = 0; c < corners; c++) {
                    text.append(' ').append(corner(random, vertices, normals));
                }
            }
            text.append(random.nextInt(20) == 0 ? "\n\n" : "\n");
        }
        return mistakes && random.nextBoolean() ? text.toString().replace("\n", "\r\n") : text.toString();
    }

    private static String number(Random random) {
        return String.valueOf((random.nextInt(2_000_001) - 1_000_000) / 1000f);
    }

    private static String corner(Random random, int vertices, int normals) {
        String vertex = String.valueOf(random.nextBoolean() ? 1 + random.nextInt(vertices) : -1 - random.nextInt(Math.min(vertices, 5)));
        if (normals == 0 || random.nextInt(3) == 0) {
            return random.nextBoolean() ? vertex : vertex + "/" + (1 + random.nextInt(9));
        }
        String normal = String.valueOf(1 + random.nextInt(normals));
        return random.nextBoolean() ? vertex + "//" + normal : vertex + "/1/" + normal;
    }
}
