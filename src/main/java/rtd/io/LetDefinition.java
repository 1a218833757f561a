package rtd.io;

/**
 * {@code let:(name):(expression)} (Part III, "Expressions, named values and the clock"): defines a name for
 * the lines below. A name is a letter, then letters, digits or '_'; not a word the expressions use, and not
 * defined twice. A plain number is kept as a statement would read it, an expression as its tree.
 */
final class LetDefinition {

    private LetDefinition() {
    }

    /** Defines the name of group {@code g} as the expression of group {@code g + 1}. */
    static void define(StatementValues v, int g) throws StatementError {
        String name = v.name(g);
        if (!ExpressionParser.isLetter((byte) name.charAt(0)) || name.indexOf('-') >= 0) {
            throw v.errorAtValue(g, 0, "the name '" + name + "' cannot be defined: a name starts with a letter, then "
                    + "letters, digits or '_'", "such as let:(size):(1)");
        }
        if (Names.isReserved(name)) {
            throw v.errorAtValue(g, 0, "'" + name + "' cannot be defined: it is a word of the expressions",
                    "choose another name; clock, pi and the functions (sin, cos, sqrt, …) keep their meaning");
        }
        Integer earlier = v.expressionNames.lineOf(name);
        if (earlier != null) {
            throw v.errorAtValue(g, 0, "a second let of '" + name + "': each name is defined once",
                    "the first '" + name + "' is at line " + earlier);
        }
        v.expressionNames.define(name, v.expression(g + 1), v.line());
    }

    /** Notes that the {@code let} being read has a mistake, once its name is read: its uses are then left out. */
    static void defineBroken(StatementValues v) {
        if (v.hasValue(0)) {
            v.expressionNames.defineBroken(v.name(0), v.line());
        }
    }
}
