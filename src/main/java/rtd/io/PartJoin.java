package rtd.io;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.image.Color;
import rtd.scene.Light;
import rtd.scene.Scene;

/**
 * Joins the {@link ScenePart}s that {@link SceneParser} read, in file order, into the scene: so
 * the scene and the messages are the same as from reading the file in one go. Joining is also
 * where what only the whole file can tell is checked: one camera, one {@code ambient}, one
 * material per name; and where the objects that name a material, which may be defined further
 * down, are built. Three slips that are no mistakes are told as warnings, located as mistakes
 * are: a material no object names, an {@code ior} without {@code transparency}, and materials in
 * a scene without a light.
 */
final class PartJoin {

    private static final String CAMERA_EXAMPLE = "orthographic_camera:(0|0|20):(0|0|-1):(50)";

    private PartJoin() {
    }

    /**
     * The scene the parts hold together, or every mistake in them, ordered by place; its warnings
     * go to {@code warnings} (null: dropped), in file order.
     */
    static Scene join(SourceText source, List<ScenePart> parts, List<SceneError> warnings) throws SceneException {
        List<ScenePart.Found> errors = new ArrayList<>();
        List<ScenePart.Located<Color>> ambients = new ArrayList<>();
        List<ScenePart.Located<ICamera>> cameras = new ArrayList<>();
        List<ScenePart.Located<ScenePart.Named>> definitions = new ArrayList<>();
        Set<String> broken = new HashSet<>();
        List<Light> lights = new ArrayList<>();
        int statements = 0;
        addLineNumbers(parts, errors);
        for (ScenePart part : parts) {
            lights.addAll(part.lights);
            errors.addAll(part.errors);
            ambients.addAll(part.ambients);
            cameras.addAll(part.cameras);
            definitions.addAll(part.materials);
            broken.addAll(part.brokenDefinitions);
            statements += part.statementCount;
        }
        for (ScenePart.Located<Color> second : ambients.subList(Math.min(1, ambients.size()), ambients.size())) {
            errors.add(found(again(second.place(), "a second 'ambient': a scene has one background colour",
                    "the first 'ambient' is at line " + ambients.get(0).place().line())));
        }
        for (ScenePart.Located<ICamera> second : cameras.subList(Math.min(1, cameras.size()), cameras.size())) {
            errors.add(found(again(second.place(), "a second camera: a scene has one",
                    "the first camera is at line " + cameras.get(0).place().line())));
        }
        Map<String, Material> materials = materials(definitions, errors);
        Set<String> named = new HashSet<>();
        for (ScenePart part : parts) {
            named.addAll(part.namedAtOnce);
        }
        List<IGeometry> objects = objects(parts, materials, broken, named, errors);
        if (errors.isEmpty() && statements == 0) {
            errors.add(found(atStart(source, "the scene is empty: it has no statements, only blanks and comments",
                    "a scene needs at least a camera, such as " + CAMERA_EXAMPLE)));
        } else if (errors.isEmpty() && cameras.isEmpty()) {
            errors.add(found(atStart(source, "the scene has no camera", "add a line such as " + CAMERA_EXAMPLE)));
        }
        if (!errors.isEmpty()) {
            errors.sort(Comparator.comparingInt(ScenePart.Found::line).thenComparingInt(ScenePart.Found::column));
            List<SceneError> shown = errors.subList(0, Math.min(SceneParser.MAX_ERRORS, errors.size())).stream()
                    .map(ScenePart.Found::error).toList();
            throw new SceneException(shown, errors.size() > SceneParser.MAX_ERRORS);
        }
        if (warnings != null) {
            warnings.addAll(MaterialWarnings.of(definitions, named, !lights.isEmpty()));
        }
        Color ambient = ambients.isEmpty() ? Color.BLACK : ambients.get(0).value();
        return new Scene(ambient, cameras.get(0).value(), objects, lights);
    }

    /** The lines that start with a line number, as one mistake at the first of them. */
    private static void addLineNumbers(List<ScenePart> parts, List<ScenePart.Found> errors) {
        SceneError first = null;
        int count = 0;
        for (ScenePart part : parts) {
            first = first != null ? first : part.firstLineNumber;
            count += part.lineNumbers;
        }
        if (first != null) {
            String more = count == 1 ? "" : count == 2 ? ", as does 1 more line" : ", as do " + (count - 1) + " more lines";
            errors.add(found(again(first, first.message() + more, first.help())));
        }
    }

    /** The materials by name; a name defined again is an error at the second definition. */
    private static Map<String, Material> materials(List<ScenePart.Located<ScenePart.Named>> definitions,
            List<ScenePart.Found> errors) {
        Map<String, ScenePart.Located<ScenePart.Named>> first = new HashMap<>();
        Map<String, Material> materials = new HashMap<>();
        for (ScenePart.Located<ScenePart.Named> definition : definitions) {
            String name = definition.value().name();
            ScenePart.Located<ScenePart.Named> earlier = first.putIfAbsent(name, definition);
            if (earlier == null) {
                materials.put(name, definition.value().material());
            } else {
                errors.add(found(again(definition.place(), "a second material '" + name + "': each name is defined once",
                        "the first '" + name + "' is at line " + earlier.place().line())));
            }
        }
        return materials;
    }

    /**
     * Every object in file order: those the parts built, and between them those that name a
     * material, built now that every material is known.
     */
    private static List<IGeometry> objects(List<ScenePart> parts, Map<String, Material> materials, Set<String> broken,
            Set<String> named, List<ScenePart.Found> errors) {
        int count = 0;
        for (ScenePart part : parts) {
            count += part.objects.size() + part.pending.size(); // a pending mesh may make more
        }
        List<IGeometry> objects = new ArrayList<>(count);
        Statement.Output out = new ObjectsOutput(objects);
        for (ScenePart part : parts) {
            int next = 0;
            for (ScenePart.Pending pending : part.pending) {
                objects.addAll(part.objects.subList(next, pending.index()));
                next = pending.index();
                named.add(build(pending.values(), materials, broken, out, errors));
            }
            objects.addAll(part.objects.subList(next, part.objects.size())); // copied in bulk: early in a run, faster than one by one
        }
        return objects;
    }

    /**
     * Builds an object that names a material, and answers the name. An unknown name is an error at
     * the name, unless its definition has a mistake, which is reported already; the rest of the
     * statement is still checked, so that one run shows all its mistakes.
     */
    private static String build(GroupValues values, Map<String, Material> materials, Set<String> broken,
            Statement.Output out, List<ScenePart.Found> errors) {
        Statement statement = values.statement();
        int group = statement.groups().size(); // the last, optional group: the material's name
        String name = values.name(group);
        Material material = materials.get(name);
        Statement.Output target = out;
        if (material == null && !broken.contains(name)) {
            String nearest = Suggestions.nearest(name, materials.keySet());
            ScenePart.addErrors(errors, values.errorAtValue(group, 0, "unknown material '" + name + "'", nearest != null
                    ? "did you mean '" + nearest + "'?"
                    : "define it with a line such as material:(" + name + "):(diffuse=0.9)"));
        }
        if (material == null) {
            material = Material.DEFAULT;
            target = new ObjectsOutput(new ArrayList<>()); // the scene has errors: the object is only checked
        }
        values.useMaterial(material);
        try {
            statement.builder().build(values, target);
        } catch (StatementError e) {
            ScenePart.addErrors(errors, e);
        }
        return name;
    }

    private static ScenePart.Found found(SceneError error) {
        return new ScenePart.Found(error.line(), error.column(), error);
    }

    private static SceneError again(SceneError place, String message, String help) {
        return new SceneError(place.file(), place.line(), place.column(), message, place.sourceLine(), help);
    }

    private static SceneError atStart(SourceText source, String message, String help) {
        int start = ByteClasses.startsWithByteOrderMark(source.bytes()) ? 3 : 0;
        return new SceneError(source.name(), 1, 1, message, source.lineText(start), help);
    }
}
