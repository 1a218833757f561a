package rtd.io;

import java.util.List;
import java.util.stream.Collectors;

/**
 * One statement of the {@link Grammar}: its keyword, its groups, the optional groups that may follow them
 * (an object's material and transform, Part II's "Light" and Part III's "Transformations"; a
 * transformation's further steps), and how it builds its value. {@link StatementReader} reads any statement
 * from this alone.
 *
 * @param optional    the groups that may follow {@code groups}, in this order, each at most once
 * @param repeatsLast whether the last optional group may follow any number of times
 */
record Statement(String keyword, List<Group> groups, List<Group> optional, boolean repeatsLast, Builder builder) {

    /** The optional groups of an object, in either order: the names of a {@code material:} and a {@code transform:}. */
    static final Group MATERIAL = Group.word("material", Group.Rule.NAME, "material");
    static final Group TRANSFORM = Group.word("transform", Group.Rule.NAME, "transform");

    /** A statement that makes a shape: it may name a material and a transform. */
    static Statement shape(String keyword, List<Group> groups, Builder builder) {
        return new Statement(keyword, groups, List.of(MATERIAL, TRANSFORM), false, builder);
    }

    /** A statement that sets something of the scene (its background, camera, a light, a material): no optional group. */
    static Statement setting(String keyword, List<Group> groups, Builder builder) {
        return new Statement(keyword, groups, List.of(), false, builder);
    }

    /** Whether it makes an object: the group itself, not an equal one, as a record's equals compares each field. */
    boolean takesMaterial() {
        return !optional.isEmpty() && optional.get(0) == MATERIAL;
    }

    int mostOptional() {
        return repeatsLast ? Integer.MAX_VALUE : optional.size();
    }

    /** Group {@code g} of the statement as written: its own groups, then the optional ones. */
    Group group(int g) {
        int own = groups.size();
        return g < own ? groups.get(g) : optional.get(Math.min(g - own, optional.size() - 1));
    }

    /** Checks what only several groups together tell (each group's own rule is checked before) and gives its value. */
    @FunctionalInterface
    interface Builder {
        void build(StatementValues values, SceneContents out) throws StatementError;
    }

    /** The statement's full form, such as {@code sphere:(x|y|z):(r):(R|G|B)[:(material)][:(transform)]}. */
    String usage() {
        return keyword + groups.stream().map(g -> ":(" + g.shape() + ")").collect(Collectors.joining())
                + optional.stream().map(g -> "[:(" + g.shape() + ")]").collect(Collectors.joining())
                + (repeatsLast ? "…" : "");
    }

    /** How many groups it takes, for "too many groups: 'sphere' takes 3, or up to 5 with a material and a transform". */
    String groupCount() {
        if (optional.isEmpty()) {
            return String.valueOf(groups.size());
        }
        return groups.size() + (takesMaterial()
                ? ", or up to " + (groups.size() + 2) + " with a material and a transform"
                : ", or " + (groups.size() + optional.size()) + " with a " + optional.get(0).meaning());
    }
}
