package rtd.io;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.image.Color;
import rtd.scene.Light;

/**
 * What one stretch of lines of a scene file holds: its objects, its {@code ambient}, camera and
 * {@code material} statements (a scene may have only one of each, or one per name, which only
 * the whole file can tell), the objects that wait for a material defined anywhere in the file,
 * and the mistakes found. {@link StatementReader} fills it; {@link PartJoin} joins the parts.
 */
final class ScenePart {

    /** A value with the place of the statement that gave it. */
    record Located<T>(T value, SceneError place) {
    }

    /** A material and the name it is defined under. */
    record Named(String name, Material material) {
    }

    /**
     * An object that names a material, to be built when every material is known: the values of
     * its statement, and how many objects of the part come before it.
     */
    record Pending(int index, GroupValues values) {
    }

    /** A mistake, and where in the scene file it is ordered (an OBJ file's, at its mesh line). */
    record Found(int line, int column, SceneError error) {
    }

    final List<IGeometry> objects;
    final List<Pending> pending = new ArrayList<>();
    final List<Located<Color>> ambients = new ArrayList<>();
    final List<Located<ICamera>> cameras = new ArrayList<>();
    final List<Located<Named>> materials = new ArrayList<>();
    final List<Light> lights = new ArrayList<>();
    final List<Found> errors = new ArrayList<>();
    /** The names of definitions ({@code material:}) that have mistakes: not unknown, only broken. */
    final Set<String> brokenDefinitions = new HashSet<>();
    /** The material names of the objects built at once, with a material defined above them ({@link #materialAbove}). */
    final Set<String> namedAtOnce = new HashSet<>();
    int statementCount;
    /**
     * The first line that starts with a line number, as the paper's listing does, and how many
     * do: they are one mistake (the listing was pasted with its numbers), reported once when the
     * parts are joined, and do not count towards {@link SceneParser#MAX_ERRORS} while reading.
     */
    SceneError firstLineNumber;
    int lineNumbers;
    /** Whether the part's last line is inside a {@code /*} comment that goes on in the next part. */
    boolean endsInBlockComment;

    /** A part for about {@code expectedObjects} objects; more are fine. */
    ScenePart(int expectedObjects) {
        objects = new ArrayList<>(expectedObjects);
    }

    /**
     * The material {@code name} if the part defines it above the line being read, else null (the
     * object then waits for the join, as the material may be defined further down). In a scene
     * without mistakes that is the file's one definition of the name, the one the join would
     * give; in a scene with mistakes the objects are only checked, and no check of an object
     * depends on its material. Most scenes define their materials at the top: their objects are
     * built as they are read, without a copy of each statement's values kept until the end.
     */
    Material materialAbove(String name) {
        for (Located<Named> definition : materials) {
            if (definition.value().name().equals(name)) {
                return definition.value().material();
            }
        }
        return null;
    }

    /** Keeps an object that names a material, at its place among the part's objects. */
    void addPending(GroupValues values) {
        pending.add(new Pending(objects.size(), values));
    }

    /** Notes a line that starts with a line number; {@code error} is the mistake if it is the first. */
    void noteLineNumber(SceneError error) {
        if (firstLineNumber == null) {
            firstLineNumber = error;
        }
        lineNumbers++;
    }

    /** Keeps the errors of a statement, ordered by its place. */
    void addErrors(StatementError e) {
        addErrors(errors, e);
    }

    /** Adds the errors of a statement to {@code errors}, ordered by its place. */
    static void addErrors(List<Found> errors, StatementError e) {
        for (SceneError error : e.errors()) {
            errors.add(new Found(e.place().line(), e.place().column(), error));
        }
    }
}
