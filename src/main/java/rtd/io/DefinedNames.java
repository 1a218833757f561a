package rtd.io;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Pattern;
import rtd.geometry.Patterned;
import rtd.geometry.Transformed;
import rtd.image.Color;
import rtd.io.SceneContents.Definition;
import rtd.io.SceneContents.Found;
import rtd.math.Matrix4;

/**
 * The one set of names that materials, patterns and transforms share (Part III, "Transformations"): each defined
 * once, above or below the lines that use it. It resolves an object's names and a pattern's transform, each
 * mistake at the name that makes it, and warns of slips that change nothing in the picture.
 */
final class DefinedNames {

    /** The key {@code ior} in a material's properties: after a '(' or '|' and blanks, before blanks and '='. */
    private static final java.util.regex.Pattern IOR_KEY =
            java.util.regex.Pattern.compile("(?<=[(|][ \\t]{0,1000})ior(?=[ \\t]*=)");

    /** What an object's names mean: its material, pattern and transform (null if none), and the names it used. */
    record ObjectNames(Material material, Pattern pattern, Matrix4 transform, List<String> names) {

        static final ObjectNames NONE = new ObjectNames(Material.DEFAULT, null, null, List.of());

        /** The object patterned, then transformed: the pattern lies in the object's own space and moves with it. */
        IGeometry dress(IGeometry object) {
            IGeometry painted = pattern == null ? object : new Patterned(object, pattern);
            return transform == null ? painted : new Transformed(painted, transform);
        }

        /** The colour a builder sees for a colour group that names a pattern: its first colour, black if unknown. */
        Color colour() {
            return pattern == null ? Color.BLACK : pattern.a();
        }
    }

    /** Each name's first definition: a {@link Material}, a {@link Pattern} or a {@link Matrix4}. */
    private final Map<String, Definition> first = new HashMap<>();
    /** Each pattern with its transform resolved, by name. */
    private final Map<String, Pattern> patterns = new HashMap<>();
    /** The names whose definitions have mistakes: not unknown, only broken. */
    private final Set<String> broken;
    /** Whether the file defines no pattern or transform: then an unknown name is an unknown material. */
    private final boolean onlyMaterials;
    private final List<Definition> definitions;
    private final Set<String> namedByPatterns = new HashSet<>();

    /** The names {@code contents} defines; a name defined twice is an error at the second definition, in file order. */
    DefinedNames(SceneContents contents, List<Found> errors) {
        broken = contents.brokenDefinitions;
        definitions = contents.definitions;
        onlyMaterials = definitions.stream().allMatch(definition -> definition.kind().equals("material"));
        definitions.forEach(definition -> define(definition, errors));
        for (Definition definition : definitions) { // a pattern's transform may be defined below it
            if (definition.transform() != null) {
                namedByPatterns.add(definition.transform());
            }
            if (definition.value() instanceof Pattern p && first.get(definition.name()) == definition) {
                Matrix4 matrix = definition.transform() == null ? null
                        : lookUp(definition.transform(), "transform", definition.transformPlace(), errors);
                patterns.put(definition.name(), new Pattern(p.kind(), p.a(), p.b(),
                        matrix == null ? Matrix4.IDENTITY : matrix));
            }
        }
    }

    private void define(Definition definition, List<Found> errors) {
        String name = definition.name();
        String kind = definition.kind();
        Definition earlier = first.putIfAbsent(name, definition);
        if (earlier != null && earlier.kind().equals(kind)) {
            errors.add(definition.place().saying("a second " + kind + " '" + name + "': each name is defined once",
                    "the first '" + name + "' is at line " + earlier.place().line()).found());
        } else if (earlier != null) {
            errors.add(definition.place().saying("'" + name + "' is defined already, as a " + earlier.kind()
                    + " at line " + earlier.place().line() + ": materials, patterns and transforms share one set of "
                    + "names", "give the " + kind + " another name, such as '" + name + "_" + kind + "'").found());
        }
    }

    /**
     * The warnings about the materials, in file order (at most {@link SceneException#MAX_ERRORS} and a line for the
     * rest, as a library of materials could give thousands), then about each pattern and transform nothing names.
     */
    List<SceneError> warnings(Set<String> named, boolean lit) {
        List<Definition> materials = definitions.stream().filter(d -> d.value() instanceof Material).toList();
        List<SceneError> warnings = new ArrayList<>();
        if (!lit && !materials.isEmpty()) {
            warnings.add(materials.get(0).place().saying("materials change nothing here: the scene has no light, so "
                    + "it is drawn in flat colours, as in the paper",
                    "add a light, such as light:(0|10|10):(255|255|255)"));
        }
        for (Definition definition : materials) {
            String name = definition.name();
            Material material = (Material) definition.value();
            if (!named.contains(name)) {
                warnings.add(definition.place().saying("material '" + name + "' is defined, but no object names it",
                        "an object names its material in its last group, such as sphere:(0|0|0):(1):(255|255|255):("
                                + name + ")"));
            }
            if (lit && material.ior() != 1 && material.transparency() <= 0) { // without a light, nothing is bent anyway
                warnings.add(atTheIor(definition.place()).saying("the ior of material '" + name + "' bends nothing: "
                        + "its transparency is 0, so no light goes through it",
                        "let light through, such as transparency=0.9, or leave ior out"));
            }
        }
        int most = SceneException.MAX_ERRORS;
        if (warnings.size() > most) {
            SceneError next = warnings.get(most);
            int more = warnings.size() - most;
            warnings.subList(most, warnings.size()).clear();
            warnings.add(new SceneError(next.file(), next.line(), next.column(), "and " + more
                    + " more warnings like these, the first of them here", null, null));
        }
        for (Definition d : definitions.stream().filter(d -> !d.kind().equals("material") && !named.contains(d.name())
                && !namedByPatterns.contains(d.name())).limit(most).toList()) {
            boolean pattern = d.kind().equals("pattern");
            warnings.add(d.place().saying(d.kind() + " '" + d.name() + "' is defined, but "
                    + (pattern ? "no object names it" : "no object or pattern names it"), pattern
                    ? "an object names its pattern in its colour group, such as sphere:(0|0|0):(1):(" + d.name() + ")"
                    : "an object names its transform after its colour, such as sphere:(0|0|0):(1):(255|255|255):("
                            + d.name() + ")"));
        }
        return warnings;
    }

    /** The place of the {@code ior} key on the material's line, after its name; the name's if it is not found. */
    private static SceneError atTheIor(SceneError name) {
        Matcher key = IOR_KEY.matcher(name.sourceLine());
        return key.find(name.column() - 1) ? new SceneError(name.file(), name.line(), key.start() + 1,
                name.message(), name.sourceLine(), name.help()) : name;
    }

    /** What an object's names mean: its last groups name a material and a transform, its colour group a pattern. */
    ObjectNames of(StatementValues values, List<Found> errors) {
        Material material = null;
        Matrix4 transform = null;
        List<String> used = new ArrayList<>();
        String unknownKind = onlyMaterials ? "material" : "material or transform";
        for (int g = values.statement().groups().size(); g < values.groupCount(); g++) {
            String name = values.name(g);
            used.add(name);
            String kind = kindOf(name);
            SceneError place = values.placeOfValue(g, 0);
            if (kind == null) {
                if (!broken.contains(name)) {
                    errors.add(place.saying("unknown " + unknownKind + " '" + name + "'", didYouMean(name, unknownKind))
                            .found());
                }
            } else if (kind.equals("pattern")) {
                errors.add(place.saying("'" + name + "' is a pattern, not a material or a transform", whereItGoes(kind))
                        .found());
            } else if (kind.equals("material") ? material != null : transform != null) {
                errors.add(place.saying("a second " + kind + " for one object: it takes at most one material and one "
                        + "transform", "give one " + kind + "; to combine transformations, list their steps in one "
                        + "transform").found());
            } else if (kind.equals("material")) {
                material = (Material) first.get(name).value();
            } else {
                transform = (Matrix4) first.get(name).value();
            }
        }
        Pattern pattern = null;
        int colour = values.patternGroup;
        if (colour >= 0) {
            String name = values.name(colour);
            used.add(name);
            pattern = lookUp(name, "pattern", values.placeOfValue(colour, 0), errors);
        }
        return new ObjectNames(material == null ? Material.DEFAULT : material, pattern, transform, used);
    }

    private String kindOf(String name) {
        Definition definition = first.get(name);
        return definition == null ? null : definition.kind();
    }

    /** The pattern or transform ({@code kind}) {@code name} used at {@code place}; else null, with an error. */
    @SuppressWarnings("unchecked")
    private <T> T lookUp(String name, String kind, SceneError place, List<Found> errors) {
        String is = kindOf(name);
        if (kind.equals(is)) {
            return (T) (is.equals("pattern") ? patterns.get(name) : first.get(name).value());
        }
        if (is != null) {
            errors.add(place.saying("'" + name + "' is a " + is + ", not a " + kind, whereItGoes(is)).found());
        } else if (!broken.contains(name)) {
            errors.add(place.saying("unknown " + kind + " '" + name + "'", didYouMean(name, kind)).found());
        }
        return null;
    }

    private String didYouMean(String name, String kind) {
        String nearest = Hints.nearest(name, first.values().stream().filter(d -> kind.contains(d.kind()))
                .map(Definition::name).toList());
        return Hints.didYouMean(nearest, switch (kind) {
            case "pattern" -> "define it with a line such as pattern:(" + name + "):(checker):(255|0|0):(255|255|0)";
            case "transform" -> "define it with a line such as transform:(" + name + "):(scale 2):(translate 0|1|0)";
            default -> onlyMaterials ? "define it with a line such as material:(" + name + "):(diffuse=0.9)"
                    : "define it with a line such as material:(" + name + "):(diffuse=0.9) or transform:(" + name
                            + "):(scale 2)";
        });
    }

    private static String whereItGoes(String kind) {
        return switch (kind) {
            case "pattern" -> "a pattern's name goes in the object's colour group: sphere:(0|0|0):(1):(checks)";
            case "material" -> "a material's name goes in one of the object's last groups: "
                    + "sphere:(0|0|0):(1):(255|0|0):(shiny)";
            default -> "a transform's name goes in one of an object's last groups, or a pattern's: "
                    + "sphere:(0|0|0):(1):(255|0|0):(stretched)";
        };
    }
}
