package rtd.io;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import rtd.geometry.Material;

/**
 * Three slips with materials that change nothing in the picture, told as warnings at the material's line: a
 * material no object names; an {@code ior} without {@code transparency}; materials in a scene without a
 * light, drawn in the paper's flat colours.
 */
final class MaterialWarnings {

    /** The key {@code ior} in a material's properties: after a '(' or '|' and blanks, before blanks and '='. */
    private static final Pattern IOR = Pattern.compile("(?<=[(|][ \\t]{0,1000})ior(?=[ \\t]*=)");

    private MaterialWarnings() {
    }

    /**
     * The warnings for the {@code definitions}, in file order, of which objects {@code named} some: at most
     * {@link SceneParser#MAX_ERRORS} and a last line for the rest, as a library of materials could give thousands.
     */
    static List<SceneError> of(List<SceneContents.Located<SceneContents.Named>> definitions, Set<String> named, boolean lit) {
        List<SceneError> warnings = new ArrayList<>();
        if (!lit && !definitions.isEmpty()) {
            warnings.add(definitions.get(0).place().saying("materials change nothing here: the scene has no light, so it is "
                    + "drawn in flat colours, as in the paper", "add a light, such as light:(0|10|10):(255|255|255)"));
        }
        for (SceneContents.Located<SceneContents.Named> definition : definitions) {
            String name = definition.value().name();
            Material material = definition.value().material();
            if (!named.contains(name)) {
                warnings.add(definition.place().saying("material '" + name + "' is defined, but no object names it",
                        "an object names its material in its last group, such as sphere:(0|0|0):(1):(255|255|255):(" + name
                                + ")"));
            }
            if (lit && material.ior() != 1 && material.transparency() <= 0) { // without a light, nothing is bent anyway
                warnings.add(atTheIor(definition.place()).saying("the ior of material '" + name + "' bends nothing: its transparency "
                        + "is 0, so no light goes through it", "let light through, such as transparency=0.9, or leave ior out"));
            }
        }
        int most = SceneParser.MAX_ERRORS;
        if (warnings.size() <= most) {
            return warnings;
        }
        SceneError next = warnings.get(most);
        List<SceneError> shown = new ArrayList<>(warnings.subList(0, most));
        shown.add(new SceneError(next.file(), next.line(), next.column(), "and " + (warnings.size() - most)
                + " more warnings like these, the first of them here", null, null));
        return shown;
    }

    /** The place of the {@code ior} key on the material's line, after its name; the name's if it is not found. */
    private static SceneError atTheIor(SceneError name) {
        Matcher key = IOR.matcher(name.sourceLine() == null ? "" : name.sourceLine());
        return key.find(Math.max(0, name.column() - 1))
                ? new SceneError(name.file(), name.line(), key.start() + 1, name.message(), name.sourceLine(), name.help()) : name;
    }
}
