package rtd.io;

import java.util.ArrayList;
import java.util.List;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Pattern;
import rtd.geometry.Patterned;
import rtd.geometry.Transformed;
import rtd.image.Color;
import rtd.math.Matrix4;

/**
 * What an object's names mean (Part III, "Transformations" and "Patterns"): its last groups name a material
 * and a transform, in either order, each at most once; its colour group may name a pattern. Resolved once
 * the whole file is read, so that each may be defined above or below the object.
 *
 * @param material  the finish ({@link Material#DEFAULT} if none is named)
 * @param pattern   the pattern, or null
 * @param transform the transformation, or null
 * @param names     the names used, for the warnings about materials that no object names
 */
record ObjectNames(Material material, Pattern pattern, Matrix4 transform, List<String> names) {

    /** An object that names nothing: the default finish, its own colour, not transformed. */
    static final ObjectNames NONE = new ObjectNames(Material.DEFAULT, null, null, List.of());

    /** These names with {@code material} as the finish. */
    ObjectNames with(Material material) {
        return new ObjectNames(material, pattern, transform, names);
    }

    /**
     * The object as its names make it: patterned if its colour group names a pattern, then transformed if
     * it names a transform, so that the pattern lies in the object's own space and moves with it.
     */
    IGeometry dress(IGeometry object) {
        IGeometry painted = pattern == null ? object : new Patterned(object, pattern);
        return transform == null ? painted : new Transformed(painted, transform);
    }

    /** The colour a builder sees for a colour group that names the pattern: its first colour (black if unknown). */
    Color colour() {
        return pattern == null ? Color.BLACK : pattern.a();
    }

    /** The names of the object whose values are {@code values}; each mistake goes to {@code errors}. */
    static ObjectNames of(StatementValues values, DefinedNames names, List<SceneContents.Found> errors) {
        Material material = null;
        Matrix4 transform = null;
        List<String> used = new ArrayList<>();
        int first = values.statement().groups().size();
        for (int g = first; g < values.groups().groupCount; g++) {
            String name = values.name(g);
            used.add(name);
            String kind = names.kindOf(name);
            SceneError place = values.placeOfValue(g, 0);
            if (kind == null) {
                if (!names.isBroken(name)) {
                    errors.add(place.saying("unknown " + names.objectNameKind() + " '" + name + "'",
                            names.didYouMean(name, names.objectNameKind())).found());
                }
            } else if (kind.equals("pattern")) {
                errors.add(place.saying("'" + name + "' is a pattern, not a material or a transform",
                        DefinedNames.whereItGoes(kind)).found());
            } else if (kind.equals("material") ? material != null : transform != null) {
                errors.add(place.saying("a second " + kind + " for one object: it takes at most one material and one "
                        + "transform", "give one " + kind + "; to combine transformations, list their steps in one transform")
                        .found());
            } else if (kind.equals("material")) {
                material = names.material(name);
            } else {
                transform = names.transform(name);
            }
        }
        Pattern pattern = null;
        int colour = values.groups().named;
        if (colour >= 0) {
            String name = values.name(colour);
            used.add(name);
            pattern = names.lookUp(name, "pattern", values.placeOfValue(colour, 0), errors);
        }
        return new ObjectNames(material == null ? Material.DEFAULT : material, pattern, transform, used);
    }
}
