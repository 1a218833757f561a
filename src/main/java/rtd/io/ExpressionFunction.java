package rtd.io;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.function.DoubleBinaryOperator;
import java.util.function.DoubleUnaryOperator;

/**
 * The functions an expression in a scene file may call (Part III, "Expressions, named values and the clock"):
 * {@code sin cos tan} take degrees, as a camera's field of view is given, and {@code asin acos atan atan2}
 * answer in degrees; {@code sqrt abs floor} take one argument, {@code min max atan2} two. Each is evaluated in
 * double precision.
 */
enum ExpressionFunction {
    SIN("x", x -> Math.sin(Math.toRadians(x))),
    COS("x", x -> Math.cos(Math.toRadians(x))),
    TAN("x", x -> Math.tan(Math.toRadians(x))),
    ASIN("x", x -> Math.toDegrees(Math.asin(x))),
    ACOS("x", x -> Math.toDegrees(Math.acos(x))),
    ATAN("x", x -> Math.toDegrees(Math.atan(x))),
    ATAN2("y, x", (y, x) -> Math.toDegrees(Math.atan2(y, x))),
    SQRT("x", Math::sqrt),
    ABS("x", Math::abs),
    FLOOR("x", Math::floor),
    MIN("a, b", Math::min),
    MAX("a, b", Math::max);

    /** Every function's name, for "did you mean …?" and for the names a {@code let} may not take. */
    static final List<String> NAMES = Arrays.stream(values()).map(ExpressionFunction::spelling).toList();

    private final String arguments;
    private final DoubleUnaryOperator one;
    private final DoubleBinaryOperator two;

    ExpressionFunction(String arguments, DoubleUnaryOperator one) {
        this.arguments = arguments;
        this.one = one;
        this.two = null;
    }

    ExpressionFunction(String arguments, DoubleBinaryOperator two) {
        this.arguments = arguments;
        this.one = null;
        this.two = two;
    }

    /** The function named {@code name} (as written in a scene, lower case), or null. */
    static ExpressionFunction named(String name) {
        return Arrays.stream(values()).filter(function -> function.spelling().equals(name)).findFirst().orElse(null);
    }

    String spelling() {
        return name().toLowerCase(Locale.ROOT);
    }

    int arity() {
        return one != null ? 1 : 2;
    }

    /** How it is called, for messages: {@code atan2(y, x)}. */
    String usage() {
        return spelling() + "(" + arguments + ")";
    }

    /** The function's value at {@code args} (as many as {@link #arity}). */
    double apply(double[] args) {
        return one != null ? one.applyAsDouble(args[0]) : two.applyAsDouble(args[0], args[1]);
    }
}
