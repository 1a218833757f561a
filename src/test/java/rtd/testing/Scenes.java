package rtd.testing;

import java.nio.file.Path;
import java.util.List;
import rtd.camera.OrthographicCamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Sphere;
import rtd.io.SceneIO;
import rtd.math.Vector3f;
import rtd.image.Color;
import rtd.scene.Scene;

/** Scenes for tests: the committed examples, and small ones built in code. */
public final class Scenes {

    /**
     * Every shape statement, each with a pattern and all but the plane with a transform, a mesh as {@code ico.obj} (the caller copies
     * {@code examples/meshes/icosphere_1.obj} there), for a perspective camera; {@code TestScenesCoverEveryShapeTest}
     * fails until a new shape is among them.
     */
    public static final String EVERY_SHAPE = String.join("\n",
            "ambient:(20|30|60)",
            "perspective_camera:(0|4|12):(at 0|0.5|0):(55)",
            "transform:(egg):(scale 1.6|0.8|1):(rotate_y 30):(translate -3|1|0)",
            "transform:(tilt):(rotate_z 25):(rotate_x -15):(translate 3|1|0)",
            "transform:(small):(scale 0.4)",
            "transform:(spin):(rotate_y 30):(translate 0|1.5|-2)",
            "transform:(lean):(rotate_z 8)",
            "pattern:(checks):(checker):(230|30|20):(250|220|40):(small)",
            "pattern:(bands):(stripes):(30|90|200):(240|240|240):(small)",
            "pattern:(glow):(gradient):(0|0|0):(255|128|0)",
            "pattern:(targets):(rings):(255|255|255):(90|90|90):(small)",
            "plane:(0|0|0):(0|1|0):(checks)",
            "sphere:(0|0|0):(1):(bands):(egg)",
            "box:(-1|-1|-1):(1|1|1):(glow):(tilt)",
            "triangle:(-1|0|0):(1|0|0):(0|1.5|0):(targets):(spin)",
            "mesh:(ico.obj):(0|0.8|2):(0.8):(bands):(small)",
            "cylinder:(-4|0|3):(-4|1.6|3):(0.5):(targets):(lean)",
            "cone:(4.5|0|-2):(1):(4.5|2.2|-2):(0.2):(checks):(lean)", "");

    private Scenes() {
    }

    /** Reads {@code examples/NAME.txt}. */
    public static Scene example(String name) {
        try {
            return SceneIO.readScene(Path.of("examples", name + ".txt"));
        } catch (Exception e) {
            throw new AssertionError("cannot read example " + name, e);
        }
    }

    /** A camera at (0,0,z) looking along −z with the given zoom. */
    public static OrthographicCamera frontCamera(float z, float zoom) {
        return new OrthographicCamera(new Vector3f(0, 0, z), new Vector3f(0, 0, -1), zoom);
    }

    /** A sphere of colour {@code rgb}. */
    public static Sphere sphere(float x, float y, float z, float r, int rgb) {
        return new Sphere(new Vector3f(x, y, z), r, Color.fromRGB(rgb));
    }

    /** A scene with a white background. */
    public static Scene scene(OrthographicCamera camera, IGeometry... objects) {
        return new Scene(Color.fromRGB(0xFFFFFF), camera, List.of(objects));
    }
}
