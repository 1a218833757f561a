package rtd.io;

import java.util.List;

/**
 * An expression of a scene file as a tree (Part III, "Expressions, named values and the clock"): a number, a
 * name ({@code pi}, {@code clock}, or one that {@code let} defined), a minus sign before an expression, two
 * expressions joined by {@code + - * / ^}, or a function called with its arguments. {@link ExpressionParser}
 * builds it; {@link #value} evaluates it in double precision for a clock. Each node knows where it starts in
 * the file, so that a value that is not a number (a division by 0 at some clock) is reported at its place.
 * It is public, and immutable, so that the POV-Ray export can write a number that uses the clock as POV-Ray's
 * own expression ({@link SceneFile#withClock}).
 */
public sealed interface Expression {

    /** The byte of the file where this part of the expression starts. */
    int start();

    /** The value at {@code clock}; a part whose value is not finite throws, naming itself. */
    double value(double clock) throws NotFinite;

    /** Whether the value depends on the clock: a number's does not. */
    default boolean usesClock() {
        return false;
    }

    /** A number as written, read as a double. */
    record Number(double number, int start) implements Expression {
        @Override
        public double value(double clock) {
            return number;
        }
    }

    /** {@code clock}: 0 unless the command line says otherwise. */
    record Clock(int start) implements Expression {
        @Override
        public double value(double clock) {
            return clock;
        }

        @Override
        public boolean usesClock() {
            return true;
        }
    }

    /** {@code pi}, or a name that a {@code let} above defined as {@code definition}. */
    record Name(String name, Expression definition, int start) implements Expression {
        @Override
        public double value(double clock) throws NotFinite {
            return definition.value(clock);
        }

        @Override
        public boolean usesClock() {
            return definition.usesClock();
        }
    }

    record Negation(Expression operand, int start) implements Expression {
        @Override
        public double value(double clock) throws NotFinite {
            return -operand.value(clock);
        }

        @Override
        public boolean usesClock() {
            return operand.usesClock();
        }
    }

    /** {@code left op right}, {@code op} one of {@code + - * / ^}; it starts where its left side does. */
    record Operation(char op, Expression left, Expression right, int opOffset) implements Expression {
        @Override
        public int start() {
            return left.start();
        }

        @Override
        public double value(double clock) throws NotFinite {
            double a = left.value(clock);
            double b = right.value(clock);
            double result = switch (op) {
                case '+' -> a + b;
                case '-' -> a - b;
                case '*' -> a * b;
                case '/' -> a / b;
                default -> Math.pow(a, b);
            };
            return NotFinite.check(result, this, b == 0 && op == '/' ? "divides by 0" : null);
        }

        @Override
        public boolean usesClock() {
            return left.usesClock() || right.usesClock();
        }
    }

    record Call(ExpressionFunction function, List<Expression> arguments, int start) implements Expression {
        public Call {
            arguments = List.copyOf(arguments);
        }

        @Override
        public double value(double clock) throws NotFinite {
            double[] args = new double[arguments.size()];
            for (int k = 0; k < args.length; k++) {
                args[k] = arguments.get(k).value(clock);
            }
            return NotFinite.check(function.apply(args), this, null);
        }

        public String functionName() {
            return function.spelling();
        }

        @Override
        public boolean usesClock() {
            return arguments.stream().anyMatch(Expression::usesClock);
        }
    }

    /** A part of an expression whose value is NaN or infinite, such as {@code 1/0} or {@code sqrt(-1)}. */
    final class NotFinite extends Exception {
        private static final long serialVersionUID = 1L;
        /** The part, what went wrong if it can tell ("divides by 0") or null, and its value. */
        final transient Expression part;
        final String why;
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
