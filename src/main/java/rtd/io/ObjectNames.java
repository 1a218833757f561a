package rtd.io;

import java.util.List;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Pattern;
import rtd.geometry.Patterned;
import rtd.geometry.Transformed;
import rtd.image.Color;
import rtd.math.Matrix4;

/**
 * What an object's names mean (Part III, "Transformations" and "Patterns"): the material and transform its
 * last groups name, the pattern its colour group names. {@link DefinedNames#of} resolves them once the whole
 * file is read, so that each may be defined above or below the object.
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
}
