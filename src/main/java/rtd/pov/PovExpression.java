package rtd.pov;

import java.math.BigDecimal;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.stream.Collectors;
import rtd.io.Expression;

/**
 * An expression of a scene file in POV-Ray's scene language, for an animation that follows POV-Ray's {@code clock}
 * (Part III, "Expressions, named values and the clock"): rtd's trigonometry is in degrees, so {@code radians()} and
 * {@code degrees()} go round it; {@code a ^ b} is {@code pow(a, b)}. A {@code let} name is POV-Ray's {@code Rtd_name},
 * {@code #declare}d once, so that a chain of {@code let}s is not doubled at every line. Parentheses only where
 * POV-Ray's order of operations would read the text otherwise, and around every minus sign not written first.
 */
final class PovExpression {

    /** How tightly each kind binds: a sum, a product, and everything written as one piece (a number, a call). */
    private static final int SUM = 1;
    private static final int PRODUCT = 2;
    private static final int ATOM = 3;

    private PovExpression() {
    }

    /** {@code e} as POV-Ray's expression of the same value. */
    static String of(Expression e) {
        return within(e, SUM);
    }

    /** {@code e}, in parentheses if it binds less tightly than {@code context} asks. */
    private static String within(Expression e, int context) {
        String text = text(e);
        return binds(e) < context ? "(" + text + ")" : text;
    }

    /** How tightly {@code e} as written binds; a minus sign as loosely as a sum, so "a * -b" is written "a * (-b)". */
    private static int binds(Expression e) {
        if (e instanceof Expression.Operation operation) {
            char op = operation.op();
            return op == '+' || op == '-' ? SUM : op == '^' ? ATOM : PRODUCT;
        }
        if (e instanceof Expression.Negation || e instanceof Expression.Number number && number.number() < 0) {
            return SUM; // a let's plain number may be negative
        }
        return ATOM;
    }

    /** {@code e} written out: an operation left to right, a sign, a name, an atom. */
    private static String text(Expression e) {
        if (e instanceof Expression.Operation operation && operation.op() == '^') {
            return "pow(" + of(operation.left()) + ", " + of(operation.right()) + ")";
        }
        if (e instanceof Expression.Operation operation) {
            int level = operation.op() == '+' || operation.op() == '-' ? SUM : PRODUCT;
            return within(operation.left(), level) + " " + operation.op() + " " + within(operation.right(), level + 1);
        }
        if (e instanceof Expression.Negation negation) {
            return "-" + within(negation.operand(), ATOM);
        }
        if (e instanceof Expression.Name name) {
            return name.name().equals("pi") ? "pi" : identifier(name); // a let's name, as declarations declares it
        }
        if (e instanceof Expression.Number number) {
            return number(number.number());
        }
        if (e instanceof Expression.Clock) {
            return "clock";
        }
        if (e instanceof Expression.Call call) {
            return call(call);
        }
        throw new IllegalArgumentException("no POV-Ray expression for " + e);
    }

    private static String identifier(Expression.Name name) {
        return "Rtd_" + name.name();
    }

    /**
     * The {@code #declare} of every {@code let} name that {@code expressions} use, directly or through other names,
     * each once and after the names its definition uses.
     */
    static String declarations(Iterable<Expression> expressions) {
        Map<String, Expression.Name> names = new LinkedHashMap<>();
        expressions.forEach(e -> collect(e, names));
        return names.values().stream()
                .map(name -> "#declare " + identifier(name) + " = " + of(name.definition()) + ";\n")
                .collect(Collectors.joining());
    }

    /** Adds the names {@code e} uses to {@code names}, each after those its definition uses. */
    private static void collect(Expression e, Map<String, Expression.Name> names) {
        if (e instanceof Expression.Name name && !name.name().equals("pi")) {
            if (!names.containsKey(name.name())) {
                collect(name.definition(), names);
                names.put(name.name(), name);
            }
        } else if (e instanceof Expression.Operation operation) {
            collect(operation.left(), names);
            collect(operation.right(), names);
        } else if (e instanceof Expression.Negation negation) {
            collect(negation.operand(), names);
        } else if (e instanceof Expression.Call call) {
            call.arguments().forEach(argument -> collect(argument, names));
        }
    }

    /** A function: angles in POV-Ray are radians, rtd's are degrees. */
    private static String call(Expression.Call call) {
        String a = of(call.arguments().get(0));
        String name = call.function().name();
        return switch (name) {
            case "sin", "cos", "tan" -> name + "(radians(" + a + "))";
            case "asin", "acos", "atan" -> "degrees(" + name + "(" + a + "))";
            case "atan2" -> "degrees(atan2(" + a + ", " + of(call.arguments().get(1)) + "))";
            case "min", "max" -> name + "(" + a + ", " + of(call.arguments().get(1)) + ")";
            case "sqrt", "abs", "floor" -> name + "(" + a + ")";
            default -> throw new IllegalArgumentException("no POV-Ray function for " + name);
        };
    }

    /** A number in its shortest decimal, plain; one that is a float (as a statement reads it), in the float's. */
    static String number(double value) {
        if (value == (float) value) {
            return PovNumbers.num((float) value);
        }
        return new BigDecimal(Double.toString(value)).stripTrailingZeros().toPlainString();
    }
}
