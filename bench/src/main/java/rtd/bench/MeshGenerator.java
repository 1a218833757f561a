package rtd.bench;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Writes triangle meshes as Wavefront OBJ files: a subdivided icosahedron (the examples' model)
 * and a terrain of n × n quads (the mesh benchmark, with its POV-Ray twin as {@code mesh2}).
 *
 * <p>Usage:
 * <pre>
 * java -cp bench/target/benchmarks.jar rtd.bench.MeshGenerator icosphere LEVEL OUT.obj [flat]
 * java -cp bench/target/benchmarks.jar rtd.bench.MeshGenerator terrain N OUT.obj [OUT.pov]
 * </pre>
 */
public final class MeshGenerator {

    private MeshGenerator() {
    }

    public static void main(String[] args) throws IOException {
        switch (args[0]) {
            case "icosphere" -> writeIcosphere(Integer.parseInt(args[1]), Path.of(args[2]),
                    args.length < 4 || !args[3].equals("flat"));
            case "terrain" -> writeTerrain(Integer.parseInt(args[1]), Path.of(args[2]),
                    args.length > 3 ? Path.of(args[3]) : null);
            default -> throw new IllegalArgumentException("icosphere or terrain, not " + args[0]);
        }
    }

    // ---- the icosahedron, each triangle split into four, `level` times, on the unit sphere ----

    /** The icosphere; with {@code smooth}, each corner names its normal ({@code vn}), else the faces are flat. */
    static void writeIcosphere(int level, Path out, boolean smooth) throws IOException {
        List<double[]> vertices = new ArrayList<>();
        List<int[]> faces = new ArrayList<>();
        double t = (1 + Math.sqrt(5)) / 2;
        double[][] corners = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t}, {0, -1, -t},
            {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
        for (double[] c : corners) {
            vertices.add(unit(c));
        }
        int[][] icosahedron = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
            {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9}, {4, 9, 5},
            {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
        faces.addAll(List.of(icosahedron));
        for (int l = 0; l < level; l++) {
            Map<Long, Integer> middles = new HashMap<>();
            List<int[]> finer = new ArrayList<>();
            for (int[] f : faces) {
                int a = middle(f[0], f[1], vertices, middles);
                int b = middle(f[1], f[2], vertices, middles);
                int c = middle(f[2], f[0], vertices, middles);
                finer.add(new int[] {f[0], a, c});
                finer.add(new int[] {f[1], b, a});
                finer.add(new int[] {f[2], c, b});
                finer.add(new int[] {a, b, c});
            }
            faces = finer;
        }
        try (BufferedWriter obj = Files.newBufferedWriter(out, StandardCharsets.UTF_8)) {
            obj.write("# An icosahedron subdivided " + level + " times: " + faces.size()
                    + " triangles on the unit sphere, " + (smooth ? "with a normal per corner" : "flat")
                    + " (rtd.bench.MeshGenerator)\n");
            obj.write("o icosphere\n");
            for (double[] v : vertices) {
                obj.write(String.format(Locale.ROOT, "v %.6f %.6f %.6f%n", v[0], v[1], v[2]));
            }
            if (smooth) {
                for (double[] v : vertices) { // on a unit sphere the normal is the point itself
                    obj.write(String.format(Locale.ROOT, "vn %.6f %.6f %.6f%n", v[0], v[1], v[2]));
                }
            }
            for (int[] f : faces) {
                obj.write(smooth
                        ? String.format(Locale.ROOT, "f %d//%d %d//%d %d//%d%n", f[0] + 1, f[0] + 1, f[1] + 1, f[1] + 1,
                                f[2] + 1, f[2] + 1)
                        : String.format(Locale.ROOT, "f %d %d %d%n", f[0] + 1, f[1] + 1, f[2] + 1));
            }
        }
    }

    private static int middle(int i, int j, List<double[]> vertices, Map<Long, Integer> middles) {
        long key = Math.min(i, j) * 1_000_000_000L + Math.max(i, j);
        return middles.computeIfAbsent(key, k -> {
            double[] a = vertices.get(i);
            double[] b = vertices.get(j);
            vertices.add(unit(new double[] {a[0] + b[0], a[1] + b[1], a[2] + b[2]}));
            return vertices.size() - 1;
        });
    }

    private static double[] unit(double[] v) {
        double length = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return new double[] {v[0] / length, v[1] / length, v[2] / length};
    }

    // ---- a terrain: heights over an n × n grid of quads, x and z in [−1, 1] ----

    static double height(double x, double z) {
        return 0.15 * Math.sin(3.1 * x) * Math.cos(2.3 * z) + 0.07 * Math.sin(7.7 * x + 1.3 * z) + 0.03 * Math.cos(13 * z - 5 * x);
    }

    static void writeTerrain(int n, Path obj, Path pov) throws IOException {
        int side = n + 1;
        try (BufferedWriter out = Files.newBufferedWriter(obj, StandardCharsets.UTF_8)) {
            out.write("# A terrain of " + n + " x " + n + " quads, " + 2L * n * n + " triangles (rtd.bench.MeshGenerator)\n");
            for (int j = 0; j < side; j++) {
                for (int i = 0; i < side; i++) {
                    double x = -1 + 2.0 * i / n;
                    double z = -1 + 2.0 * j / n;
                    out.write(String.format(Locale.ROOT, "v %.5f %.5f %.5f%n", x, height(x, z), z));
                }
            }
            for (int j = 0; j < n; j++) {
                for (int i = 0; i < n; i++) {
                    int a = j * side + i + 1;
                    out.write(String.format(Locale.ROOT, "f %d %d %d %d%n", a, a + side, a + side + 1, a + 1));
                }
            }
        }
        if (pov != null) {
            writeTerrainPov(n, pov);
        }
    }

    /** The terrain as POV-Ray's mesh2, with the camera and colours of bench/mesh.txt's twin. */
    private static void writeTerrainPov(int n, Path pov) throws IOException {
        int side = n + 1;
        try (BufferedWriter out = Files.newBufferedWriter(pov, StandardCharsets.UTF_8)) {
            out.write("#version 3.7;\nglobal_settings { assumed_gamma 1.0 ambient_light 1 }\n");
            out.write("background { rgb <16/255, 18/255, 28/255> }\n");
            // rtd: perspective_camera:(0|1.2|2.2):(0|-0.55|-1):(60), shift (0|0|0), scale 1. POV-Ray's z is rtd's −z.
            out.write("camera { perspective location <0, 1.2, -2.2> look_at <0, 1.2 - 0.55, -2.2 + 1>"
                    + " right -x*1920/1080 angle 60 }\n");
            out.write("mesh2 {\n vertex_vectors { " + side * side + ",\n");
            for (int j = 0; j < side; j++) {
                for (int i = 0; i < side; i++) {
                    double x = -1 + 2.0 * i / n;
                    double z = -1 + 2.0 * j / n;
                    out.write(String.format(Locale.ROOT, "<%.5f,%.5f,%.5f>%n", x, height(x, z), -z));
                }
            }
            out.write(" }\n face_indices { " + 2L * n * n + ",\n");
            for (int j = 0; j < n; j++) {
                for (int i = 0; i < n; i++) {
                    int a = j * side + i;
                    out.write(String.format(Locale.ROOT, "<%d,%d,%d>,<%d,%d,%d>%n", a, a + side, a + side + 1, a,
                            a + side + 1, a + 1));
                }
            }
            out.write(" }\n pigment { rgb <90/255, 160/255, 80/255> } finish { ambient 1 diffuse 0 }\n}\n");
        }
    }
}
