package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.charset.StandardCharsets;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import rtd.geometry.Box;
import rtd.geometry.Cone;
import rtd.geometry.Cylinder;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.math.Vector3f;
import rtd.scene.Scene;
import rtd.testing.Describe;

/**
 * Random scenes of every kind of object, with materials defined before and after their use and
 * meshes, written as text and read back: they come back the same, and the same in any parts.
 * (The scenes as objects for the render paths' tests are {@link rtd.testing.MixedScenes}'s.)
 */
@DisplayName("Scenes of every kind of object, written as text")
class WrittenScenesTest {

    private static final String MESH = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 1\nf 1 2 3 4\nf -1 -2 -4\n";


    @TempDir
    Path folder;

    /** A random scene as text, and the objects it must read as. */
    private record Written(String text, List<IGeometry> objects) {
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void comeBackTheSame(long seed) throws IOException, SceneException {
        Files.writeString(folder.resolve("m.obj"), MESH);
        Written written = write(new Random(seed), 150);
        Scene whole = SceneIO.parseScene("scene.txt", written.text().getBytes(StandardCharsets.UTF_8), folder, null);
        assertThat(Describe.objects(whole.objects())).isEqualTo(Describe.objects(written.objects()));
    }

    /** A new statement that makes an object is written here too, or this test says so. */
    @Test
    void writeEveryStatementThatMakesAnObject() {
        String text = write(new Random(1), 150).text();
        for (Statement statement : Grammar.STATEMENTS) {
            if (statement.takesMaterial()) {
                assertThat(text).as("a '%s' statement", statement.keyword()).contains("\n" + statement.keyword() + ":(");
            }
        }
    }

    private static Written write(Random random, int count) {
        List<String> lines = new ArrayList<>(List.of("ambient:(1|2|3)", "perspective_camera:(0|0|20):(0|0|-1):(60)"));
        List<IGeometry> objects = new ArrayList<>();
        Material[] materials = new Material[4];
        for (int m = 0; m < materials.length; m++) {
            materials[m] = new Material(random.nextInt(10) / 10f, 0.9f, 0.9f, 200, random.nextInt(3), 0, 1 + random.nextInt(5) / 4f);
        }
        for (int i = 0; i < count; i++) {
            int m = random.nextInt(materials.length + 1) - 1; // -1: no material group
            Material material = m < 0 ? Material.DEFAULT : materials[m];
            String suffix = m < 0 ? "" : ":(m" + m + ")";
            Color colour = new Color(random.nextInt(256), random.nextInt(256), random.nextInt(256));
            Vector3f a = point(random);
            Vector3f b = new Vector3f(0.5f + random.nextInt(90) / 8f, 0.5f + random.nextInt(90) / 8f, 0.5f + random.nextInt(90) / 8f);
            switch (random.nextInt(7)) {
                case 0 -> {
                    float r = 0.1f + random.nextInt(30) / 10f;
                    objects.add(new Sphere(a, r, colour, material));
                    lines.add("sphere:(" + vector(a) + "):(" + r + "):(" + colour(colour) + ")" + suffix);
                }
                case 1 -> {
                    objects.add(new Plane(a, b, colour, material));
                    lines.add("plane:(" + vector(a) + "):(" + vector(b) + "):(" + colour(colour) + ")" + suffix);
                }
                case 2 -> {
                    Vector3f c = a.add(new Vector3f(0, 1, 0));
                    Vector3f d = a.add(new Vector3f(1, 0, 0)); // never on one line with a and c
                    objects.add(new Triangle(a, c, d, colour, material));
                    lines.add("triangle:(" + vector(a) + "):(" + vector(c) + "):(" + vector(d) + "):(" + colour(colour) + ")" + suffix);
                }
                case 3 -> {
                    Vector3f far = a.add(b);
                    objects.add(Box.between(far, a, colour, material));
                    lines.add("box:(" + vector(far) + "):(" + vector(a) + "):(" + colour(colour) + ")" + suffix);
                }
                case 5 -> {
                    float r = 0.1f + random.nextInt(30) / 10f;
                    objects.add(new Cylinder(a, a.add(b), r, colour, material));
                    lines.add("cylinder:(" + vector(a) + "):(" + vector(a.add(b)) + "):(" + r + "):(" + colour(colour) + ")" + suffix);
                }
                case 6 -> {
                    float r = random.nextInt(30) / 10f;
                    objects.add(new Cone(a, r, a.add(b), 0.5f, colour, material));
                    lines.add("cone:(" + vector(a) + "):(" + r + "):(" + vector(a.add(b)) + "):(0.5):(" + colour(colour) + ")" + suffix);
                }
                default -> {
                    float scale = 1 + random.nextInt(4);
                    objects.addAll(new ObjMeshOfTest().triangles(a, scale, colour, material));
                    lines.add("mesh:(m.obj):(" + vector(a) + "):(" + scale + "):(" + colour(colour) + ")" + suffix);
                }
            }
        }
        for (int m = 0; m < materials.length; m++) { // anywhere: before or after their use
            Material x = materials[m];
            lines.add(random.nextInt(lines.size()), "material:(m" + m + "):(ambient=" + x.ambient() + "|reflective="
                    + x.reflective() + "|ior=" + x.ior() + ")");
        }
        return new Written(String.join("\n", lines) + "\n", objects);
    }

    /** The triangles that {@link #MESH} must give: a fan of two, then one with relative indices. */
    private static final class ObjMeshOfTest {
        List<IGeometry> triangles(Vector3f shift, float s, Color colour, Material material) {
            Vector3f[] v = {new Vector3f(0, 0, 0), new Vector3f(1, 0, 0), new Vector3f(1, 1, 0), new Vector3f(0, 1, 1)};
            Vector3f[] p = new Vector3f[4];
            for (int i = 0; i < 4; i++) {
                p[i] = new Vector3f(s * v[i].x() + shift.x(), s * v[i].y() + shift.y(), s * v[i].z() + shift.z());
            }
            return List.of(new Triangle(p[0], p[1], p[2], colour, material), new Triangle(p[0], p[2], p[3], colour, material),
                    new Triangle(p[3], p[2], p[0], colour, material));
        }
    }

    private static Vector3f point(Random random) {
        return new Vector3f(random.nextInt(200) / 8f - 12, random.nextInt(200) / 8f - 12, random.nextInt(200) / 8f - 12);
    }

    private static String vector(Vector3f v) {
        return (v.x() + "|" + v.y() + "|" + v.z()).toLowerCase(Locale.ROOT);
    }

    private static String colour(Color c) {
        return c.red() + "|" + c.green() + "|" + c.blue();
    }
}
