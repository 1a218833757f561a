package rtd.io;

import java.util.List;
import java.util.stream.Collectors;
import rtd.camera.ICamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.image.Color;
import rtd.scene.Light;

/**
 * One statement of the {@link Grammar}: its keyword, its groups, whether it takes a last, optional material
 * group (Part II, "Light"), and how it builds its value. {@link StatementReader} reads any statement from
 * this alone.
 */
record Statement(String keyword, List<Group> groups, boolean takesMaterial, Builder builder) {

    /** The optional last group of an object: the name of a {@code material:}. */
    static final Group MATERIAL = Group.name("material", "material");

    Statement {
        groups = List.copyOf(groups);
    }

    /** A statement that makes an object, a shape: it may name a material in a last group. */
    static Statement shape(String keyword, List<Group> groups, Builder builder) {
        return new Statement(keyword, groups, true, builder);
    }

    /** A statement that sets something of the scene (its background, camera, a light, a material): no material group. */
    static Statement setting(String keyword, List<Group> groups, Builder builder) {
        return new Statement(keyword, groups, false, builder);
    }

    /**
     * Checks the values (a broken rule is an error at its value) and gives what the statement makes to
     * {@code out}.
     */
    @FunctionalInterface
    interface Builder {
        void build(StatementValues values, Output out) throws StatementError;
    }

    /** Where the values that statements make go: the scene being read. */
    interface Output {
        void ambient(Color colour);

        void camera(ICamera camera);

        /** One object, at the statement's place among the objects. */
        void object(IGeometry object);

        /** Several objects, in order, at the statement's place: a mesh's triangles. */
        void objects(List<IGeometry> objects);

        /** A finish that objects may name, defined under {@code name}. */
        void material(String name, Material material);

        void light(Light light);

        /** A warning about the statement that holds only if the scene has a light (a shaded scene). */
        void warningIfLit(SceneError warning);
    }

    /** The statement's full form, such as {@code sphere:(x|y|z):(r):(R|G|B)[:(material)]}. */
    String usage() {
        return keyword + groups.stream().map(g -> ":(" + g.shape() + ")").collect(Collectors.joining())
                + (takesMaterial ? "[:(" + MATERIAL.shape() + ")]" : "");
    }

    /** How many groups it takes, for "too many groups: 'sphere' takes 3, or 4 with a material". */
    String groupCount() {
        return groups.size() + (takesMaterial ? ", or " + (groups.size() + 1) + " with a material" : "");
    }
}
