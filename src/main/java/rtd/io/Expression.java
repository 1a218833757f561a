package rtd.io;

import java.util.List;
import java.util.function.DoubleBinaryOperator;
import java.util.function.DoubleUnaryOperator;

/**
 * An expression of a scene file as an immutable tree (Part III, "Expressions, named values and the clock"),
 * evaluated in double precision for a clock. Each node knows where it starts in the file, so that a value that is
 * not finite is reported at its place; the POV-Ray export writes a tree that uses the clock as POV-Ray's own.
 */
public sealed interface Expression {

    int start();

    record Number(double number, int start) implements Expression {
    }

    /** {@code clock}: 0 unless the command line says otherwise. */
    record Clock(int start) implements Expression {
    }

    /** {@code pi}, or a name that a {@code let} above defined as {@code definition}. */
    record Name(String name, Expression definition, int start) implements Expression {
    }

    record Negation(Expression operand, int start) implements Expression {
    }

    /** {@code left op right}, {@code op} one of {@code + - * / ^}; it starts where its left side does. */
    record Operation(char op, Expression left, Expression right, int opOffset) implements Expression {
        @Override
        public int start() {
            return left.start();
        }
    }

    record Call(Function function, List<Expression> arguments, int start) implements Expression {
        public Call {
            arguments = List.copyOf(arguments);
        }
    }

    /** The value at {@code clock}; a part whose value is not finite throws, naming itself. */
    default double value(double clock) throws NotFinite {
        if (this instanceof Number number) {
            return number.number;
        } else if (this instanceof Clock) {
            return clock;
        } else if (this instanceof Name name) {
            return name.definition.value(clock);
        } else if (this instanceof Negation negation) {
            return -negation.operand.value(clock);
        } else if (this instanceof Operation operation) {
            double a = operation.left.value(clock);
            double b = operation.right.value(clock);
            double result = switch (operation.op) {
                case '+' -> a + b;
                case '-' -> a - b;
                case '*' -> a * b;
                case '/' -> a / b;
                default -> Math.pow(a, b);
            };
            return NotFinite.check(result, this, b == 0 && operation.op == '/' ? "divides by 0" : null);
        }
        Call call = (Call) this;
        double a = call.arguments.get(0).value(clock);
        double b = call.arguments.size() > 1 ? call.arguments.get(1).value(clock) : 0;
        return NotFinite.check(call.function.rule.applyAsDouble(a, b), this, null);
    }

    default boolean usesClock() {
        return this instanceof Clock || this instanceof Name name && name.definition.usesClock()
                || this instanceof Negation negation && negation.operand.usesClock()
                || this instanceof Operation operation && (operation.left.usesClock() || operation.right.usesClock())
                || this instanceof Call call && call.arguments.stream().anyMatch(Expression::usesClock);
    }

    /**
     * A function an expression may call, such as {@code atan2(y, x)}: {@code sin cos tan} take degrees, as a
     * camera's field of view is given, and {@code asin acos atan atan2} answer in degrees.
     */
    record Function(String name, String arguments, DoubleBinaryOperator rule) {

        static final List<Function> ALL = List.of(one("sin", x -> Math.sin(Math.toRadians(x))),
                one("cos", x -> Math.cos(Math.toRadians(x))), one("tan", x -> Math.tan(Math.toRadians(x))),
                one("asin", x -> Math.toDegrees(Math.asin(x))), one("acos", x -> Math.toDegrees(Math.acos(x))),
                one("atan", x -> Math.toDegrees(Math.atan(x))),
                new Function("atan2", "y, x", (y, x) -> Math.toDegrees(Math.atan2(y, x))), one("sqrt", Math::sqrt),
                one("abs", Math::abs), one("floor", Math::floor), new Function("min", "a, b", Math::min),
                new Function("max", "a, b", Math::max));
        /** Every function's name, for "did you mean …?" and for the names a {@code let} may not take. */
        static final List<String> NAMES = ALL.stream().map(Function::name).toList();

        private static Function one(String name, DoubleUnaryOperator rule) {
            return new Function(name, "x", (x, none) -> rule.applyAsDouble(x));
        }

        /** The function named {@code name}, or null. */
        static Function named(String name) {
            return ALL.stream().filter(function -> function.name.equals(name)).findFirst().orElse(null);
        }

        int arity() {
            return arguments.contains(",") ? 2 : 1;
        }

        /** How it is called, for messages: {@code atan2(y, x)}. */
        String usage() {
            return name + "(" + arguments + ")";
        }
    }

    /** A part of an expression whose value is NaN or infinite, such as {@code 1/0} or {@code sqrt(-1)}. */
    final class NotFinite extends Exception {
        private static final long serialVersionUID = 1L;
        /** What went wrong if it can tell ("divides by 0"), else null. */
        final String why;
        final transient Expression part;
        final double value;

        NotFinite(Expression part, String why, double value) {
            super(why, null, false, false);
            this.part = part;
            this.why = why;
            this.value = value;
        }

        /** {@code value} if it is finite; else the part that gave it fails. */
        static double check(double value, Expression part, String why) throws NotFinite {
            if (Double.isFinite(value)) {
                return value;
            }
            throw new NotFinite(part, why, value);
        }
    }
}
