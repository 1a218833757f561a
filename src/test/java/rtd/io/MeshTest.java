package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;
import static org.assertj.core.data.Offset.offset;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.math.Vector3f;
import rtd.scene.Scene;

/** {@code mesh:} reads the triangles of a Wavefront OBJ file, as real modelling tools write them. */
@DisplayName("Meshes from OBJ files")
class MeshTest {

    private static final String CAMERA = "orthographic_camera:(0|0|20):(0|0|-1):(50)\n";
    private static final String SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

    @TempDir
    Path folder;

    private List<IGeometry> mesh(String obj) throws Exception {
        return scene(obj, "mesh:(model.obj):(0|0|0):(1):(255|0|0)").objects();
    }

    private Scene scene(String obj, String lines) throws Exception {
        Files.writeString(folder.resolve("model.obj"), obj);
        return SceneIO.parseScene("scene.txt", (CAMERA + lines).getBytes(StandardCharsets.UTF_8), folder, null);
    }

    private List<SceneError> errors(String obj) throws IOException {
        Files.write(folder.resolve("model.obj"), obj.getBytes(StandardCharsets.UTF_8));
        return catchThrowableOfType(SceneException.class, () -> SceneIO.parseScene("scene.txt",
                (CAMERA + "\nmesh:(model.obj):(0|0|0):(1):(255|0|0)").getBytes(StandardCharsets.UTF_8), folder, null))
                .errors();
    }

    private static List<Vector3f> corners(IGeometry object) {
        Triangle t = (Triangle) object;
        return List.of(t.corner(0), t.corner(1), t.corner(2));
    }

    private static Vector3f v(float x, float y, float z) {
        return new Vector3f(x, y, z);
    }

    @Test
    void aTriangleIsReadWithItsCornersInOrder() throws Exception {
        List<IGeometry> objects = mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        assertThat(objects).hasSize(1);
        assertThat(corners(objects.get(0))).containsExactly(v(0, 0, 0), v(1, 0, 0), v(0, 1, 0));
        assertThat(((Triangle) objects.get(0)).isSmooth()).isFalse();
        assertThat(objects.get(0).color()).isEqualTo(new Color(255, 0, 0));
        assertThat(objects.get(0).material()).isEqualTo(Material.DEFAULT);
    }

    @Test
    void eachCornerIsScaledThenShifted() throws Exception {
        List<IGeometry> objects = scene("v 1 2 3\nv 2 2 3\nv 1 3 3\nf 1 2 3", "mesh:(model.obj):(10|20|30):(2):(0|0|0)").objects();
        assertThat(corners(objects.get(0))).containsExactly(v(12, 24, 36), v(14, 24, 36), v(12, 26, 36));
    }

    @Test
    void quadsAndPolygonsBecomeFansAroundTheirFirstCorner() throws Exception {
        List<IGeometry> objects = mesh(SQUARE + "v 0.5 2 0\nf 1 2 3 4\nf 1 2 3 5 4\n");
        assertThat(objects).hasSize(2 + 3);
        assertThat(corners(objects.get(0))).containsExactly(v(0, 0, 0), v(1, 0, 0), v(1, 1, 0));
        assertThat(corners(objects.get(1))).containsExactly(v(0, 0, 0), v(1, 1, 0), v(0, 1, 0));
        assertThat(corners(objects.get(4))).containsExactly(v(0, 0, 0), v(0.5f, 2, 0), v(0, 1, 0));
    }

    @Test
    void negativeIndicesCountBackFromTheLastVertexReadSoFar() throws Exception {
        List<IGeometry> objects = mesh("v 9 9 9\n" + SQUARE + "f -4 -3 -2\nv 5 5 5\nf -1 -2 1");
        assertThat(corners(objects.get(0))).containsExactly(v(0, 0, 0), v(1, 0, 0), v(1, 1, 0));
        assertThat(corners(objects.get(1))).containsExactly(v(5, 5, 5), v(0, 1, 0), v(9, 9, 9));
    }

    @Test
    void everyFormOfCornerIsRead() throws Exception {
        String obj = SQUARE + "vt 0 0\nvt 1 0\nvn 0 0 1\nf 1/1 2/2 3/1\nf 1//1 3//1 4//1\nf 1/2/1 2/1/1 3/99/1\n";
        List<IGeometry> objects = mesh(obj);
        assertThat(objects).extracting(o -> ((Triangle) o).isSmooth()).containsExactly(false, true, true);
        assertThat(corners(objects.get(1))).containsExactly(v(0, 0, 0), v(1, 1, 0), v(0, 1, 0));
    }

    @Test
    void normalsOnEveryCornerMakeASmoothTriangleBlendingThem() throws Exception {
        Triangle t = (Triangle) mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 0\nvn 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//3").get(0);
        assertThat(t.isSmooth()).isTrue();
        assertThat(t.normalAt(v(0, 0, 0))).isEqualTo(v(1, 0, 0)); // at a corner: that corner's normal
        Vector3f middle = t.normalAt(v(1 / 3f, 1 / 3f, 0));
        assertThat(middle.x()).isCloseTo(middle.y(), offset(1e-6f));
        assertThat(middle.z()).isCloseTo(middle.x(), offset(1e-6f));
    }

    @Test
    void aFaceWithANormalOnSomeCornersOnlyIsFlat() throws Exception {
        Triangle t = (Triangle) mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2 3//1").get(0);
        assertThat(t.isSmooth()).isFalse();
    }

    @Test
    void smoothFacesAmongThousandsOfFlatOnesKeepTheirNormalsAndTheFlatOnesNone() throws Exception {
        StringBuilder obj = new StringBuilder("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 0\nvn 0 1 0\nvn 0 0 1\n");
        for (int f = 0; f < 5000; f++) {
            obj.append(f == 1500 || f == 4999 ? "f 1//3 2//2 3//1\n" : "f 1 2 3\n");
        }
        List<IGeometry> objects = mesh(obj.toString());
        assertThat(objects).hasSize(5000);
        for (int f = 0; f < objects.size(); f++) {
            Triangle t = (Triangle) objects.get(f);
            assertThat(t.isSmooth()).as("face %d", f).isEqualTo(f == 1500 || f == 4999);
        }
        Triangle last = (Triangle) objects.get(4999);
        assertThat(new Vector3f[] {last.cornerNormal(0), last.cornerNormal(1), last.cornerNormal(2)})
                .containsExactly(v(0, 0, 1), v(0, 1, 0), v(1, 0, 0));
    }

    @Test
    void whatRealFilesHoldBesideIsSkipped() throws Exception {
        String obj = "# Blender 4.0\r\nmtllib cube.mtl\r\no Cube\r\n\r\nv 0 0 0 1.0\r\nv\t1  0   0\r\n"
                + "v 0 1 0 0.5 0.25 0.125\r\nvt 0.5 0.5\r\nvp 1 2\r\ng side\r\nusemtl Material.001\r\ns off\r\n"
                + "l 1 2\r\n   \t\r\nf 1 2 3 # the only face\r\ncstype bezier \u00e4\u00fc\u00df\r\n#f 9 9 9\r\nf\t1\t2  3   ";
        List<IGeometry> objects = mesh(obj);
        assertThat(objects).hasSize(2);
        assertThat(corners(objects.get(1))).containsExactly(v(0, 0, 0), v(1, 0, 0), v(0, 1, 0));
    }

    @Test
    void theLastLineNeedsNoLineBreakAndAByteOrderMarkIsFine() throws Exception {
        assertThat(mesh("\uFEFFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3")).hasSize(1);
    }

    @Test
    void aFaceOfZeroAreaIsKept() throws Exception {
        assertThat(mesh("v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\nf 1 1 1\n")).hasSize(2);
    }

    @Test
    void aFileWithoutFacesIsAnErrorAtTheMeshsPathNotAMeshOfNoTriangles() {
        for (String obj : new String[] {"", "v 0 0 0\nv 1 0 0\nv 0 1 0\nF 1 2 3\n"}) {
            SceneException error = catchThrowableOfType(() -> mesh(obj), SceneException.class);
            assertThat(error).as(obj).isNotNull();
            assertThat(error.report()).contains("scene.txt:2:7: error: the mesh file 'model.obj' has no faces", "'F'");
        }
    }

    @Test
    void theTrianglesStandAtTheMeshLineAmongTheOtherObjectsInFaceOrder() throws Exception {
        Scene scene = scene(SQUARE + "f 1 2 3\nf 1 3 4\n", "sphere:(0|0|0):(1):(0|0|0)\nmesh:(model.obj):(0|0|0):(1):(1|1|1)\n"
                + "sphere:(0|0|1):(1):(0|0|0)\nmesh:(model.obj):(0|0|5):(1):(2|2|2):(shiny)\nmaterial:(shiny):(specular=1)");
        List<IGeometry> objects = scene.objects();
        assertThat(objects).extracting(IGeometry::kind)
                .containsExactly("sphere", "triangle", "triangle", "sphere", "triangle", "triangle");
        assertThat(((Sphere) objects.get(3)).center()).isEqualTo(v(0, 0, 1));
        assertThat(corners(objects.get(5)).get(2)).isEqualTo(v(0, 1, 5));
        assertThat(objects.get(5).material().specular()).isEqualTo(1f);
        assertThat(objects.get(5).color()).isEqualTo(new Color(2, 2, 2));
    }

    @Test
    void thePathIsRelativeToTheSceneFilesFolder() throws Exception {
        Files.createDirectories(folder.resolve("models"));
        Files.writeString(folder.resolve("models/tri.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        Path sceneFile = folder.resolve("scene.txt");
        Files.writeString(sceneFile, CAMERA + "mesh:( models/tri.obj ):(0|0|0):(1):(255|0|0)\n");
        assertThat(SceneIO.readScene(sceneFile).objects()).hasSize(1);
    }

    @Test
    void aMistakeInTheObjFileIsLocatedThereAndNamesTheSceneLine() throws Exception {
        Files.createDirectories(folder.resolve("models"));
        Files.writeString(folder.resolve("models/bad.obj"), "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
        Path sceneFile = folder.resolve("scene.txt");
        Files.writeString(sceneFile, CAMERA + "\nmesh:(models/bad.obj):(0|0|0):(1):(255|0|0)\n");
        SceneError error = catchThrowableOfType(SceneException.class, () -> SceneIO.readScene(sceneFile)).errors().get(0);
        assertThat(error.file()).isEqualTo(folder.resolve("models/bad.obj").toString());
        assertThat(error.line()).isEqualTo(3);
        assertThat(error.column()).isEqualTo(7);
        assertThat(error.message()).isEqualTo("the vertex index 3 is out of range: 2 vertices come before this face");
        assertThat(error.sourceLine()).isEqualTo("f 1 2 3");
        assertThat(error.help()).endsWith("; this file is used by " + sceneFile + ":3");
    }

    @Test
    void everyMistakeInTheObjFileIsReportedInItsOrderAtTheMeshLine() throws IOException {
        Files.writeString(folder.resolve("model.obj"), "v 0 0 x\nf 1 2\nf 1 0 1\n");
        SceneException e = catchThrowableOfType(SceneException.class, () -> SceneIO.parseScene("scene.txt",
                (CAMERA + "ambient:(1|2|3)\nmesh:(model.obj):(0|0|0):(1):(255|0|0)\nsphere:(0|0|0):(-1):(0|0|0)\n"
                        + "ambient:(1|2|3)").getBytes(StandardCharsets.UTF_8), folder, null));
        assertThat(e.errors()).extracting(err -> err.file() + ":" + err.line())
                .containsExactly("model.obj:1", "model.obj:2", "model.obj:3", "scene.txt:4", "scene.txt:5");
    }

    @Test
    void eachMistakeInAnObjFileHasItsMessage() throws IOException {
        assertThat(errors("v 0 0\n").get(0).message()).isEqualTo("expected 3 numbers (x y z) after 'v', found 2");
        assertThat(errors("vn 1 x 0\n").get(0).message()).isEqualTo("expected a number, found 'x'");
        assertThat(errors("v 0 NaN 0\n").get(0).message()).isEqualTo("the y of the vertex must be a finite number, found NaN");
        assertThat(errors("v 0 0 0\nf 1 1\n").get(0).message()).isEqualTo("a face needs at least 3 corners, found 2");
        assertThat(errors("v 0 0 0\nf 1 0 1\n").get(0).message()).isEqualTo("a vertex index is never 0: they count from 1");
        assertThat(errors("v 0 0 0\nf 1 1 -2\n").get(0).message())
                .isEqualTo("the vertex index -2 is out of range: 1 vertex comes before this face");
        assertThat(errors("v 0 0 0\nvn 0 0 1\nf 1//1 1//2 1//1\n").get(0).message())
                .isEqualTo("the normal index 2 is out of range: 1 normal comes before this face");
        assertThat(errors("v 0 0 0\nf 1 a 1\n").get(0).message()).isEqualTo("expected a corner of the face, found 'a'");
        assertThat(errors("v 0 0 0\nf 1 1/1/x 1\n").get(0).message()).isEqualTo("expected a corner of the face, found '1/1/x'");
    }

    @Test
    void anErrorInAnObjFileIsAtTheCornerThatCausesIt() throws IOException {
        SceneError error = errors("v 0 0 0\nvn 0 0 1\n\tf  1//1 1//1 1//7\n").get(0);
        assertThat(error.line()).isEqualTo(3);
        assertThat(error.column()).isEqualTo(18); // at the normal's index
        assertThat(error.format()).contains(" 3 | \tf  1//1 1//1 1//7\n   | \t                ^\n");
    }

    @Test
    void anObjFileWithANulByteIsNoText() throws IOException {
        SceneError error = errors("v 0 0 0\nv 1\0 0 0\n").get(0);
        assertThat(error.message()).isEqualTo("this is not a text file: found a NUL byte");
        assertThat(error.line()).isEqualTo(2);
        assertThat(error.column()).isEqualTo(4);
    }

    @Test
    void aMillionTrianglesAreRead() throws Exception {
        int nx = 1000; // a grid of nx × ny squares, two triangles each
        int ny = 500;
        StringBuilder obj = new StringBuilder(40 * nx * ny);
        for (int y = 0; y <= ny; y++) {
            for (int x = 0; x <= nx; x++) {
                obj.append("v ").append(x).append(' ').append(y).append(' ').append((x * y) % 7).append('\n');
            }
        }
        for (int y = 0; y < ny; y++) {
            for (int x = 0; x < nx; x++) {
                int a = y * (nx + 1) + x + 1;
                obj.append("f ").append(a).append(' ').append(a + 1).append(' ').append(a + nx + 2).append('\n');
                obj.append("f ").append(a).append(' ').append(a + nx + 2).append(' ').append(a + nx + 1).append('\n');
            }
        }
        List<IGeometry> objects = mesh(obj.toString());
        assertThat(objects).hasSize(1_000_000);
        assertThat(corners(objects.get(objects.size() - 1))).containsExactly(v(nx - 1, ny - 1, ((nx - 1) * (ny - 1)) % 7),
                v(nx, ny, (nx * ny) % 7), v(nx - 1, ny, ((nx - 1) * ny) % 7));
    }
    @Test
    void aLargeMeshsTrianglesHoldTheNumbersOfTrianglesMadeOneByOne() throws Exception {
        java.util.Random random = new java.util.Random(7);
        StringBuilder obj = new StringBuilder();
        for (int i = 0; i < 3000; i++) {
            obj.append("v ").append(random.nextFloat() * 10 - 5).append(' ').append(random.nextFloat()).append(' ')
                    .append(random.nextGaussian()).append('\n');
            obj.append("vn ").append(random.nextFloat()).append(' ').append(random.nextFloat()).append(" 1\n");
        }
        for (int f = 0; f < 40_000; f++) { // enough to be placed in parallel
            int a = 1 + random.nextInt(3000);
            int b = 1 + random.nextInt(3000);
            int c = 1 + random.nextInt(3000);
            obj.append(f % 3 == 0 ? "f " + a + "//" + b + " " + b + "//" + c + " " + c + "//" + a : "f " + a + " " + b + " " + c)
                    .append('\n');
        }
        Scene scene = scene(obj.toString(), "mesh:(model.obj):(1|-2|0.5):(1.7):(255|0|0)");
        assertThat(scene.objects()).hasSize(40_000);
        for (IGeometry object : scene.objects()) {
            Triangle t = (Triangle) object;
            Vector3f[] normals = t.isSmooth() ? new Vector3f[] {t.cornerNormal(0), t.cornerNormal(1), t.cornerNormal(2)} : null;
            Triangle alone = new Triangle(t.corner(0), t.corner(1), t.corner(2), normals, t.color(), t.material());
            assertThat(java.util.Arrays.copyOfRange(t.numbers(), t.numbersAt(), t.numbersAt() + Triangle.NUMBERS))
                    .isEqualTo(alone.numbers());
            assertThat(t.bounds()).isEqualTo(alone.bounds());
        }
    }

    @Test
    void aMeshMissingFromAStandardInputSceneIsLookedForInTheFolderRtdRunsIn() {
        byte[] scene = (CAMERA + "mesh:(no-such-model.obj):(0|0|0):(1):(255|0|0)\n").getBytes(StandardCharsets.UTF_8);
        SceneException e = catchThrowableOfType(
                () -> SceneFile.read(new java.io.ByteArrayInputStream(scene), SceneIO.STDIN_NAME).once(null),
                SceneException.class);
        assertThat(e.errors().get(0).help()).isEqualTo("the scene comes from standard input, so a mesh's path is "
                + "relative to the folder rtd runs in; or give the full path");
    }
}
