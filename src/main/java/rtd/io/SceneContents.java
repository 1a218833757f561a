package rtd.io;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Pattern;
import rtd.image.Color;
import rtd.math.Matrix4;
import rtd.scene.Light;

/**
 * What the statements of a scene file make, as the {@link Grammar}'s builders give it, with the places that
 * {@link SceneFile} needs to check what only the whole file tells (one camera, one definition per name); the
 * objects that wait for a name defined further down; the mistakes found.
 */
final class SceneContents {

    /** A value with the place of the statement that gave it. */
    record Located<T>(T value, SceneError place) {
    }

    /** A name's {@link Material}, {@link Pattern} or {@link Matrix4}; a pattern may name its transform (else null). */
    record Definition(String name, String kind, Object value, SceneError place, String transform,
            SceneError transformPlace) {
    }

    /** An object built when every name is known: how many objects come before it, and its values. */
    private record Pending(int index, StatementValues values) {
    }

    /** A mistake, and where in the scene file it is ordered (an OBJ file's, at its mesh line). */
    record Found(int line, int column, SceneError error) {
    }

    final List<IGeometry> objects;
    private final List<Pending> pending = new ArrayList<>();
    final List<Located<Color>> ambients = new ArrayList<>();
    final List<Located<ICamera>> cameras = new ArrayList<>();
    /** The materials, patterns and transforms, in file order. */
    final List<Definition> definitions = new ArrayList<>();
    /** Each material's first definition by name, the material of an object below it. */
    final Map<String, Material> materials = new HashMap<>();
    final List<Light> lights = new ArrayList<>();
    final List<Found> errors = new ArrayList<>();
    /** Warnings that hold only if the scene has a light, in the order their statements were built. */
    final List<SceneError> litWarnings = new ArrayList<>();
    /** The names of definitions ({@code material:}) that have mistakes: not unknown, only broken. */
    final Set<String> brokenDefinitions = new HashSet<>();
    /** The material names of the objects built at once, with a material defined above them. */
    final Set<String> namedAtOnce = new HashSet<>();
    int statementCount;
    /** The first line that starts with a line number, and how many do: one mistake, reported once. */
    SceneError firstLineNumber;
    int lineNumbers;
    /** Where {@link #object} puts objects: {@link #objects}, or the list a pending object is built into. */
    private List<IGeometry> into;
    /** The values of the statement being built, which the reader refills, for the places of what it makes. */
    StatementValues values;

    SceneContents(int expectedObjects) {
        objects = new ArrayList<>(expectedObjects);
        into = objects;
    }

    /** Keeps an object that names a material not known yet, at its place among the objects, for {@link #allObjects}. */
    void addPending(StatementValues objectValues) {
        pending.add(new Pending(objects.size(), objectValues.copy()));
    }

    /** Adds what {@code part}, the next lines read on their own, made: it has no mistake and no definition. */
    void append(SceneContents part) {
        part.pending.forEach(object -> pending.add(new Pending(objects.size() + object.index(), object.values())));
        objects.addAll(part.objects);
        ambients.addAll(part.ambients);
        cameras.addAll(part.cameras);
        lights.addAll(part.lights);
        litWarnings.addAll(part.litWarnings);
        namedAtOnce.addAll(part.namedAtOnce);
        statementCount += part.statementCount;
    }

    /** Notes a line that starts with a line number: the first is kept, the others counted. */
    void noteLineNumber(SceneError place) {
        if (lineNumbers++ == 0) {
            firstLineNumber = place;
        }
    }

    /** Every object in file order, the pending ones built now with {@code names}, which go to {@code named}. */
    List<IGeometry> allObjects(DefinedNames names, Set<String> named) {
        if (pending.isEmpty()) {
            return objects;
        }
        List<IGeometry> all = new ArrayList<>(objects.size() + pending.size());
        int next = 0;
        for (Pending object : pending) {
            all.addAll(objects.subList(next, object.index()));
            next = object.index();
            int before = errors.size();
            values = object.values();
            values.names = names.of(values, errors);
            named.addAll(values.names.names());
            into = errors.size() > before ? new ArrayList<>() : all; // with a name not right, only checked
            try {
                values.build(this);
            } catch (SceneException e) {
                addErrors(e);
            }
        }
        all.addAll(objects.subList(next, objects.size()));
        return all;
    }

    void ambient(Color colour) {
        ambients.add(new Located<>(colour, values.placeOfStatement()));
        recorder().ambient(values);
    }

    void camera(ICamera camera) {
        cameras.add(new Located<>(camera, values.placeOfStatement()));
        recorder().camera(values);
    }

    void light(Light light) {
        lights.add(light);
        if (light.area() == null) {
            recorder().part(light, values);
        } else {
            recorder().unwritten(values); // an area light's samples: the export writes them frame by frame
        }
    }

    /** One object, at the statement's place among the objects. */
    void object(IGeometry object) {
        IGeometry dressed = values.names.dress(object);
        into.add(dressed);
        recorder().part(dressed, values);
    }

    /** Several objects, in order, at the statement's place: a mesh's triangles. */
    void objects(List<IGeometry> more) {
        more.forEach(object -> into.add(values.names.dress(object)));
        recorder().unwritten(values);
    }

    /** A material, pattern or transform, as {@code kind} says; a pattern may name a transform (else null). */
    void define(String name, String kind, Object value, String transform) {
        SceneError transformPlace = transform == null ? null
                : values.placeOfValue(values.statement().groups().size(), 0);
        definitions.add(new Definition(name, kind, value, values.placeOfValue(0, 0), transform, transformPlace));
        if (value instanceof Material material) {
            materials.putIfAbsent(name, material);
        }
        recorder().unwritten(values);
    }

    /** Where the numbers that use the clock are noted. */
    private ClockedScene.Recorder recorder() {
        return values.expressionNames.recorder;
    }

    /** Keeps the errors of a statement, ordered by its place. */
    void addErrors(SceneException e) {
        for (SceneError error : e.errors()) {
            errors.add(new Found(e.place.line(), e.place.column(), error));
        }
    }
}
