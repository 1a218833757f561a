package rtd.io;

import java.util.List;
import java.util.stream.Collectors;

/**
 * One statement of the {@link Grammar}: its keyword, its groups, the optional groups that may follow them in
 * order, each once unless {@code repeatsLast} lets the last repeat (an object's material and transform; a
 * transformation's steps), and how it builds its value. {@link StatementReader} reads any statement from this.
 */
record Statement(String keyword, List<Group> groups, List<Group> optional, boolean repeatsLast, Builder builder) {

    /** The optional groups of an object: the names of a {@code material:} and a {@code transform:}. */
    static final Group MATERIAL = Group.word("material", Group.Rule.NAME, "material");
    static final Group TRANSFORM = Group.word("transform", Group.Rule.NAME, "transform");

    /** A statement that makes a shape: it may name a material and a transform. */
    static Statement shape(String keyword, List<Group> groups, Builder builder) {
        return new Statement(keyword, groups, List.of(MATERIAL, TRANSFORM), false, builder);
    }

    /** A statement that sets something of the scene (a camera, a light, a material): no optional group. */
    static Statement setting(String keyword, List<Group> groups, Builder builder) {
        return new Statement(keyword, groups, List.of(), false, builder);
    }

    /** Whether it makes an object: the group itself, not an equal one, as a record's equals compares each field. */
    boolean takesMaterial() {
        return !optional.isEmpty() && optional.get(0) == MATERIAL;
    }

    /** Group {@code g} of the statement as written: its own groups, then the optional ones. */
    Group group(int g) {
        int own = groups.size();
        return g < own ? groups.get(g) : optional.get(Math.min(g - own, optional.size() - 1));
    }

    /** Checks what only several groups together tell (each group's rule is checked before) and gives its value. */
    @FunctionalInterface
    interface Builder {
        void build(StatementValues values, SceneContents out) throws SceneException;
    }

    /** The statement's full form, such as {@code sphere:(x|y|z):(r):(R|G|B)[:(material)][:(transform)]}. */
    String usage() {
        return keyword + groups.stream().map(g -> ":(" + g.shape() + ")").collect(Collectors.joining())
                + optional.stream().map(g -> "[:(" + g.shape() + ")]").collect(Collectors.joining())
                + (repeatsLast ? "…" : "");
    }

    /** For "too many groups: 'sphere' takes 3, or up to 5 with a material and a transform". */
    String groupCount() {
        if (optional.isEmpty()) {
            return String.valueOf(groups.size());
        }
        return groups.size() + (takesMaterial()
                ? ", or up to " + (groups.size() + 2) + " with a material and a transform"
                : ", or " + (groups.size() + optional.size()) + " with a " + optional.get(0).meaning());
    }
}
