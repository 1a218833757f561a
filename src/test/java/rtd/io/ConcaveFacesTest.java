package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.scene.Scene;
import rtd.testing.Renders;

/** A face of more than three corners is split so that its triangles cover the face and nothing else. */
@DisplayName("Faces of OBJ files that are not convex")
class ConcaveFacesTest {

    @TempDir
    Path folder;

    private static ObjMesh read(String obj) throws SceneException {
        return ObjReader.read(new SourceText("model.obj", obj.getBytes(StandardCharsets.UTF_8)));
    }

    private static int[] corners(ObjMesh mesh) {
        return Arrays.copyOf(mesh.corners(), 3 * mesh.count());
    }

    /**
     * An L of area 3, its corners from the top of its upright bar: A(1|2), B(0|2), C(0|0), D(2|0),
     * E(2|1), F(1|1), turning left, F the one corner that turns right. The fan from A would cover
     * the square (1..2|1..2) outside the L. Ear clipping cuts off A (F A B, which holds no other
     * corner), then B (F B C), then C (F C D), and D E F is left: areas ½ + 1 + 1 + ½ = 3.
     */
    @Test
    void anLShapedHexagonIsCutIntoItsEars() throws SceneException {
        ObjMesh mesh = read("v 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nf 1 2 3 4 5 6\n");
        assertThat(corners(mesh)).containsExactly(5, 0, 1, 5, 1, 2, 5, 2, 3, 3, 4, 5);
    }

    @Test
    void aConvexFaceIsStillAFanAroundItsFirstCorner() throws SceneException {
        ObjMesh mesh = read("v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 3 0\nv -1 1 0\nf 1 2 3 4 5\n");
        assertThat(corners(mesh)).containsExactly(0, 1, 2, 0, 2, 3, 0, 3, 4);
    }

    @Test
    void aFaceWhoseCornersLieOnOneLineIsAFanToo() throws SceneException {
        ObjMesh mesh = read("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3 4\n");
        assertThat(corners(mesh)).containsExactly(0, 1, 2, 0, 2, 3);
    }

    /**
     * A ring as one face, as assimp's concave_polygon.obj stores one: the outer circle (radius 2,
     * 32 corners) turning left, a slit from its first corner in to the inner circle (radius 1),
     * the inner circle turning right, and the slit back. The orthographic camera's ray through
     * the centre pixel (the corner of pixel (10|10) of 21 × 21, at x' = y' = 0) meets the plane
     * at the origin, in the hole: background. The ray of pixel (10|3) meets it at y = 7/5 = 1.4,
     * on the ring, far from the slit along +x.
     */
    @Test
    void aRingStoredAsOneFaceShowsTheBackgroundThroughItsHole() throws Exception {
        StringBuilder obj = new StringBuilder();
        for (double radius : new double[] {2, 1}) {
            for (int k = 0; k < 32; k++) {
                double angle = 2 * Math.PI * k / 32;
                obj.append(String.format(Locale.ROOT, "v %.6f %.6f 0%n", radius * Math.cos(angle),
                        radius * Math.sin(angle)));
            }
        }
        obj.append("f");
        for (int k = 1; k <= 32; k++) {
            obj.append(' ').append(k); // the outer circle, turning left
        }
        obj.append(" 1 33"); // the slit in
        for (int k = 64; k >= 33; k--) {
            obj.append(' ').append(k); // the inner circle, turning right, back to its first corner
        }
        obj.append('\n');
        Files.writeString(folder.resolve("ring.obj"), obj);
        Scene scene = SceneIO.parseScene("scene.txt", ("ambient:(0|0|255)\northographic_camera:(0|0|10):(0|0|-1):(5)\n"
                + "mesh:(ring.obj):(0|0|0):(1):(255|0|0)\n").getBytes(StandardCharsets.UTF_8), folder, null);

        int[] pixels = Renders.paper(scene, 21, 21);

        assertThat(pixels[10 * 21 + 10]).as("the centre").isEqualTo(0x0000FF);
        assertThat(pixels[3 * 21 + 10]).as("the ring at y = 1.4").isEqualTo(0xFF0000);
        assertThat(pixels[17 * 21 + 10]).as("the ring at y = -1.4").isEqualTo(0xFF0000);
    }

    @Test
    void aFaceIsCutAsIfItCameFirstWhateverFacesCameBefore() {
        Random random = new Random(23);
        EarClipping shared = new EarClipping();
        for (int f = 0; f < 20_000; f++) {
            int count = 3 + random.nextInt(random.nextInt(4) == 0 ? 8 : 2); // quads the most, as in real files
            float[] vertices = new float[3 * count];
            int[] corners = new int[count];
            for (int k = 0; k < count; k++) {
                corners[k] = random.nextInt(5) == 0 ? random.nextInt(count) : k; // now and then a corner twice
                for (int axis = 0; axis < 3; axis++) { // a grid of few places: faces on a line, folded, crossed
                    vertices[3 * k + axis] = axis == 2 && random.nextBoolean() ? 0 : random.nextInt(4) - 1.5f;
                }
            }
            int[] expected = Arrays.copyOf(new EarClipping().triangles(corners, count, vertices), 3 * (count - 2));
            int[] cut = Arrays.copyOf(shared.triangles(corners, count, vertices), 3 * (count - 2));
            assertThat(cut).as("face %d of %d corners %s", f, count, Arrays.toString(vertices)).isEqualTo(expected);
        }
    }

    /**
     * The L of {@link #anLShapedHexagonIsCutIntoItsEars} with a normal at each corner, corner k's normal k + 1: each
     * triangle of the ears F A B, F B C, F C D, D E F keeps its corners' own normals.
     */
    @Test
    void aConcaveFaceWithANormalAtEachCornerKeepsThemInItsEars() throws SceneException {
        ObjMesh mesh = read("v 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\n" + "vn 0 0 1\n".repeat(6)
                + "f 1//1 2//2 3//3 4//4 5//5 6//6\n");
        assertThat(corners(mesh)).containsExactly(5, 0, 1, 5, 1, 2, 5, 2, 3, 3, 4, 5);
        assertThat(Arrays.copyOf(mesh.cornerNormals(), 12)).containsExactly(5, 0, 1, 5, 1, 2, 5, 2, 3, 3, 4, 5);
    }

    /**
     * The L with normals at A, B and F only: of its ears, only F A B has a normal at all three corners and keeps
     * them; the others have none. Its fan around A would have dropped them: no triangle of it is F A B.
     */
    @Test
    void aConcaveFaceWithNormalsAtSomeCornersKeepsThemWhereATriangleHasThree() throws SceneException {
        ObjMesh mesh = read("v 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\n" + "vn 0 0 1\n".repeat(3)
                + "f 1//1 2//2 3 4 5 6//3\n");
        assertThat(corners(mesh)).containsExactly(5, 0, 1, 5, 1, 2, 5, 2, 3, 3, 4, 5);
        assertThat(Arrays.copyOf(mesh.cornerNormals(), 12))
                .containsExactly(2, 0, 1, -1, -1, -1, -1, -1, -1, -1, -1, -1);
    }

    /** Random faces of 3 to 10 corners, read from one file, are cut as each one is cut alone, in the file's order. */
    @Test
    void theFacesOfAFileAreCutAsEachFaceAlone() throws SceneException {
        Random random = new Random(7);
        StringBuilder obj = new StringBuilder();
        List<Integer> expected = new ArrayList<>();
        int vertexCount = 0;
        for (int f = 0; f < 500; f++) {
            int count = 3 + random.nextInt(8);
            float[] vertices = new float[3 * count];
            int[] corners = new int[count];
            StringBuilder face = new StringBuilder("f");
            for (int k = 0; k < count; k++) {
                corners[k] = k;
                for (int axis = 0; axis < 3; axis++) { // few places: faces folded, crossed, on a line
                    vertices[3 * k + axis] = axis == 2 && random.nextBoolean() ? 0 : random.nextInt(4) - 1.5f;
                }
                obj.append(String.format(Locale.ROOT, "v %s %s %s%n", vertices[3 * k], vertices[3 * k + 1],
                        vertices[3 * k + 2]));
                face.append(' ').append(vertexCount + k + 1);
            }
            obj.append(face).append('\n');
            int[] cut = new EarClipping().triangles(corners, count, vertices);
            for (int c = 0; c < 3 * (count - 2); c++) {
                expected.add(vertexCount + cut[c]);
            }
            vertexCount += count;
        }
        assertThat(corners(read(obj.toString()))).containsExactly(expected.stream().mapToInt(Integer::intValue)
                .toArray());
    }

    @Test
    void aQuadIsToldAFanByItsQuickTestExactlyWhenTheGeneralTestSaysSo() {
        Random random = new Random(7);
        EarClipping general = new EarClipping();
        int[] corners = {0, 1, 2, 3};
        int fans = 0;
        for (int n = 0; n < 20_000; n++) {
            float[] v = new float[12];
            int family = n % 4;
            for (int k = 0; k < 4; k++) {
                double angle = 2 * Math.PI * k / 4 + (family == 0 ? 0.3 * random.nextDouble() : random.nextDouble());
                // family 1: one corner pulled in past the diagonal of its neighbours, a dart concave there
                double radius = family == 1 && k == n / 4 % 4 ? -0.05 - 0.45 * random.nextDouble() : 1;
                v[3 * k] = (float) (radius * Math.cos(angle));
                v[3 * k + 1] = (float) (radius * Math.sin(angle));
                v[3 * k + 2] = family == 2 ? (float) random.nextGaussian() : 0; // family 2: not flat
            }
            if (family == 3) { // a tilted plane, now and then with a corner on another's place
                for (int k = 0; k < 4; k++) {
                    float x = v[3 * k];
                    float y = v[3 * k + 1];
                    v[3 * k] = 0.6f * x - 0.8f * y;
                    v[3 * k + 1] = 0.48f * x + 0.36f * y;
                    v[3 * k + 2] = 0.64f * x + 0.48f * y + 3;
                }
                int k = random.nextInt(4);
                if (random.nextInt(4) == 0) {
                    System.arraycopy(v, 3 * ((k + 1) % 4), v, 3 * k, 3);
                }
            }
            boolean quick = EarClipping.isFanQuad(v, 0, 3, 6, 9);
            assertThat(quick).as("quad %d: %s", n, Arrays.toString(v)).isEqualTo(general.isFan(corners, 4, v));
            fans += quick ? 1 : 0;
        }
        assertThat(fans).as("fans among 20,000 quads").isBetween(10_000, 19_000);
        for (float odd : new float[] {Float.NaN, Float.POSITIVE_INFINITY, -0f}) {
            float[] v = {odd, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
            assertThat(EarClipping.isFanQuad(v, 0, 3, 6, 9)).as("a corner at x = %s", odd)
                    .isEqualTo(general.isFan(corners, 4, v));
        }
    }
}
