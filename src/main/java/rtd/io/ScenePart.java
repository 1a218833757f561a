package rtd.io;

import java.util.ArrayList;
import java.util.List;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.image.Color;

/**
 * What one stretch of lines of a scene file holds: its objects, its {@code ambient} and camera
 * statements (a scene may have only one of each, which only the whole file can tell), and the
 * mistakes found in it. {@link StatementReader} fills it; {@link SceneParser} joins the parts.
 */
final class ScenePart {

    /** A value with the place of the statement that gave it. */
    record Located<T>(T value, SceneError place) {
    }

    final List<IGeometry> objects = new ArrayList<>();
    final List<Located<Color>> ambients = new ArrayList<>();
    final List<Located<ICamera>> cameras = new ArrayList<>();
    final List<SceneError> errors = new ArrayList<>();
    int statementCount;
}
