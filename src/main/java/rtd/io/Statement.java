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
    static final Group MATERIAL = Group.name("material", "material");
    static final Group TRANSFORM = Group.name("transform", "transform");

    /** A statement that makes a shape: its colour may name a pattern, and it may name a material and a transform. */
    static Statement shape(String keyword, List<Group> groups, Builder builder) {
        return new Statement(keyword, groups.stream().map(Group::orPatternName).toList(), List.of(MATERIAL, TRANSFORM),
                false, builder);
    }

    /** A statement that sets something of the scene (its background, camera, a light, a material): no optional group. */
    static Statement setting(String keyword, List<Group> groups, Builder builder) {
        return new Statement(keyword, groups, List.of(), false, builder);
    }

    /**
     * Whether it makes an object, which may name a material and a transform. The group itself, not an equal one:
     * asked of every line, and a record's {@code equals} would compare every field.
     */
    boolean takesMaterial() {
        return !optional.isEmpty() && optional.get(0) == MATERIAL;
    }

    int mostOptional() {
        return repeatsLast ? Integer.MAX_VALUE : optional.size();
    }

    Group optional(int k) {
        return optional.get(Math.min(k, optional.size() - 1));
    }

    /** Checks the values (a broken rule is an error at its value) and gives what the statement makes to {@code out}. */
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
