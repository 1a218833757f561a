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
