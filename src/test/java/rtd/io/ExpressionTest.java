package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import rtd.geometry.Sphere;
import rtd.scene.Scene;

/** Expressions in a scene's numbers, {@code let} and the clock (Part III), with values worked out by hand. */
@DisplayName("Expressions in a scene file")
class ExpressionTest {

    private static final String CAMERA = "orthographic_camera:(0|0|20):(0|0|-1):(50)\n";

    /** The scene of {@code lines} (after a camera) at {@code clock}. */
    static Scene scene(String lines, double clock) throws SceneException {
        return SceneFile.of("scene.txt", (CAMERA + lines).getBytes(StandardCharsets.UTF_8), Path.of("")).at(clock, null);
    }

    /** The x of the first sphere's centre, written as {@code expression}, at {@code clock}. */
    private static float x(String expression, double clock) throws SceneException {
        return ((Sphere) scene("sphere:(" + expression + "|0|0):(1):(9|9|9)\n", clock).objects().get(0)).center().x();
    }

    private static float x(String expression) throws SceneException {
        return x(expression, 0);
    }

    /** The only error of {@code lines} (after a camera, on line 2 on), at {@code clock}. */
    static SceneError error(String lines, double clock) {
        SceneException e = catchThrowableOfType(SceneException.class, () -> scene(lines, clock));
        assertThat(e).as("a mistake").isNotNull();
        assertThat(e.errors()).hasSize(1);
        return e.errors().get(0);
    }

    @Nested
    @DisplayName("Values")
    class Values {

        @ParameterizedTest(name = "{0} = {1}")
        @CsvSource(delimiter = ';', value = {
            "1 + 2 * 3; 7", "(1 + 2) * 3; 9", "10 - 4 - 3; 3", "12 / 3 / 2; 2", "2 ^ 3 ^ 2; 512", "-2^2; -4",
            "(-2)^2; 4", "2^-1; 0.5", "- -3; 3", "+4; 4", "-3 * -2; 6", "2*3 - 4/8; 5.5", "1e1 * 2; 20"})
        void followTheOperatorsPrecedence(String expression, float value) throws SceneException {
            assertThat(x(expression)).isEqualTo(value);
        }

        @ParameterizedTest(name = "{0} = {1}")
        @CsvSource(delimiter = ';', value = {
            "sin(30); 0.5", "cos(60); 0.5", "tan(45); 1", "asin(0.5); 30", "acos(0.5); 60", "atan(1); 45",
            "atan2(1, 0); 90", "atan2(0, -1); 180", "sqrt(16); 4", "abs(-2.5); 2.5", "floor(-1.5); -2",
            "min(3, -1); -1", "max(3, -1); 3", "sin(90) + cos(0); 2"})
        void takeAndGiveDegrees(String expression, float value) throws SceneException {
            assertThat(x(expression)).isCloseTo(value, org.assertj.core.data.Offset.offset(1e-6f));
        }

        @Test
        void piIsTheCircleConstantRoundedToFloatOnce() throws SceneException {
            assertThat(x("pi")).isEqualTo((float) Math.PI);
            assertThat(x("2*pi")).isEqualTo((float) (2 * Math.PI));
        }

        /** 0.1 + 0.2 in double is 0.30000000000000004, which rounds to the float nearest 0.3: once, at the end. */
        @Test
        void evaluateInDoubleAndRoundOnce() throws SceneException {
            assertThat(x("0.1 + 0.2")).isEqualTo(0.3f);
            assertThat(x("1/3")).isEqualTo((float) (1.0 / 3));
        }

        @Test
        void aPlainNumberIsReadAsFloatParseFloatDoes() throws SceneException {
            assertThat(x("0.1")).isEqualTo(Float.parseFloat("0.1"));
            assertThat(x("-7.25e-3")).isEqualTo(Float.parseFloat("-7.25e-3"));
        }

        @Test
        void theClockIsZeroUnlessGiven() throws SceneException {
            assertThat(x("10*clock")).isEqualTo(0);
            assertThat(x("10*clock", 0.75)).isEqualTo(7.5f);
            assertThat(x("20*sin(360*clock)", 0.25)).isEqualTo(20);
        }

        @Test
        void letNamesAValueForTheLinesBelow() throws SceneException {
            Scene scene = scene("let:(r):(1.5)\nlet:(d):(2*r + clock)\nsphere:(d|r|0):(r):(9|9|9)\n", 0.5);
            Sphere sphere = (Sphere) scene.objects().get(0);
            assertThat(sphere.center().x()).isEqualTo(3.5f);
            assertThat(sphere.center().y()).isEqualTo(1.5f);
            assertThat(sphere.radius()).isEqualTo(1.5f);
        }

        @Test
        void anExpressionMayStandInEveryNumberGroupAndProperty() throws SceneException {
            Scene scene = scene("material:(m):(reflective=1/4|ior=1+0.5)\nlight:(0|2*5|0):(255|255|255)\n"
                    + "sphere:(0|0|0):(sqrt(4)):(100+1|0|0):(m)\n", 0);
            Sphere sphere = (Sphere) scene.objects().get(0);
            assertThat(sphere.radius()).isEqualTo(2);
            assertThat(sphere.material().reflective()).isEqualTo(0.25f);
            assertThat(sphere.material().ior()).isEqualTo(1.5f);
            assertThat(scene.lights().get(0).position().y()).isEqualTo(10);
            assertThat(sphere.color().red()).isEqualTo(101);
        }

        /** 127.5 rounds up to 128, 127.49 down to 127; a plain colour number must still be whole. */
        @Test
        void anExpressionInAColourIsRoundedHalfUp() throws SceneException {
            Sphere sphere = (Sphere) scene("sphere:(0|0|0):(1):(255/2|127.49+0|0.4*1)\n", 0).objects().get(0);
            assertThat(sphere.color().red()).isEqualTo(128);
            assertThat(sphere.color().green()).isEqualTo(127);
            assertThat(sphere.color().blue()).isEqualTo(0);
            assertThat(error("sphere:(0|0|0):(1):(127.5|0|0)\n", 0).message())
                    .isEqualTo("the red channel must be a whole number from 0 to 255, found 127.5");
        }

        @Test
        void theSceneTellsWhetherItUsesTheClock() throws SceneException {
            SceneFile still = SceneFile.of("s.txt", (CAMERA + "sphere:(0|0|0):(2*3):(9|9|9)\n").getBytes(StandardCharsets.UTF_8),
                    Path.of(""));
            still.at(0.5, null);
            assertThat(still.usesClock()).isFalse();
            SceneFile moving = SceneFile.of("m.txt", (CAMERA + "let:(t):(clock)\nsphere:(t|0|0):(1):(9|9|9)\n")
                    .getBytes(StandardCharsets.UTF_8), Path.of(""));
            moving.at(0.5, null);
            assertThat(moving.usesClock()).isTrue();
        }
    }

    @Nested
    @DisplayName("Mistakes, each at its column")
    class Mistakes {

        /** The only mistake of {@code lines} (from line 2) at {@code clock} is at {@code line:column} and says so. */
        private void assertError(String lines, double clock, int line, int column, String message, String help) {
            SceneError error = error(lines + "\n", clock);
            assertThat(error.message()).isEqualTo(message);
            assertThat(error.line()).isEqualTo(line);
            assertThat(error.column()).as("the column of: " + message).isEqualTo(column);
            if (help != null) {
                assertThat(error.help()).isEqualTo(help);
            }
        }

        private void assertError(String line, int column, String message, String help) {
            assertError(line, 0, 2, column, message, help);
        }

        @Test
        void aMisspeltNameGetsDidYouMean() {
            assertError("sphere:(10*clok|0|0):(1):(9|9|9)", 12, "unknown name 'clok'", "did you mean 'clock'?");
            assertError("sphere:(clok|0|0):(1):(9|9|9)", 9, "unknown name 'clok'", "did you mean 'clock'?");
            assertError("let:(radius):(2)\nsphere:(0|0|0):(2*radus):(9|9|9)", 0, 3, 19, "unknown name 'radus'",
                    "did you mean 'radius'?");
            assertError("sphere:(2*x|0|0):(1):(9|9|9)", 11, "unknown name 'x'",
                    "define it above this line with let:(x):(1), or use clock or pi");
        }

        @Test
        void aMisspeltFunctionGetsDidYouMean() {
            assertError("sphere:(sine(30)|0|0):(1):(9|9|9)", 9, "unknown function 'sine'", "did you mean 'sin'?");
        }

        @Test
        void aMissingClosingParenthesisIsFoundWhereItShouldStand() {
            assertError("sphere:(sin(30|0|0):(1):(9|9|9)", 15,
                    "expected an operator (+ - * / ^) or ')' to close 'sin(' at column 12, found '|'",
                    "every '(' in an expression needs its ')'");
            assertError("sphere:((1+2|0|0):(1):(9|9|9)", 13,
                    "expected an operator (+ - * / ^) or ')' to close the '(' at column 9, found '|'", null);
        }

        @Test
        void aFunctionWithTheWrongNumberOfArgumentsSaysHowToCallIt() {
            assertError("sphere:(atan2(1)|0|0):(1):(9|9|9)", 9, "'atan2' takes 2 arguments, found 1",
                    "write it as atan2(y, x)");
            assertError("sphere:(1+max(1, 2, 3)|0|0):(1):(9|9|9)", 11, "'max' takes 2 arguments, found 3",
                    "write it as max(a, b)");
            assertError("sphere:(2*sin|0|0):(1):(9|9|9)", 11,
                    "'sin' is a function, and it needs its argument in parentheses", "write it as sin(x)");
        }

        @Test
        void anOperatorWithoutItsNumberIsFoundAtTheGap() {
            assertError("sphere:(2*|0|0):(1):(9|9|9)", 11, "expected a number, a name or '(' in an expression, found '|'",
                    "an operator needs a number on either side");
            assertError("sphere:(2*3 pi|0|0):(1):(9|9|9)", 13,
                    "expected an operator (+ - * / ^), '|' or ')' after 2*3, found 'pi'", "a product is written with '*', such as 2*x");
        }

        @Test
        void aValueThatIsNotFiniteIsFoundAtThePartThatFails() {
            assertError("sphere:(1/(clock-0.5)|0|0):(1):(9|9|9)", 0.5, 2, 10,
                    "'1/(clock-0.5)' is not a finite number at clock = 0.5: this part of it divides by 0", null);
            assertError("sphere:(1+sqrt(-1)|0|0):(1):(9|9|9)", 0, 2, 11,
                    "'1+sqrt(-1)' is not a finite number: this part of it is not a number (NaN)", null);
            assertError("sphere:(1e30*1e30|0|0):(1):(9|9|9)", 0, 2, 9,
                    "'1e30*1e30' is too large for a float", "a float holds numbers up to about 3.4e38");
        }

        @Test
        void aRuleBrokenAtSomeClockNamesTheClock() {
            assertError("sphere:(0|0|0):(1-2*clock):(9|9|9)", 0.75, 2, 17,
                    "the radius must be greater than 0, found 1-2*clock, which is -0.5 at clock = 0.75", null);
            assertError("sphere:(0|0|0):(1):(255+1|0|0)", 0, 2, 21,
                    "the red channel must be from 0 to 255, found 255+1, which is 256", null);
        }

        @Test
        void letRefusesAReservedWordABadNameAndASecondDefinition() {
            assertError("let:(clock):(1)", 6, "'clock' cannot be defined: it is a word of the expressions", null);
            assertError("let:(sqrt):(1)", 6, "'sqrt' cannot be defined: it is a word of the expressions", null);
            assertError("let:(2a):(1)", 6, "the name '2a' cannot be defined: a name starts with a letter, then letters, "
                    + "digits or '_'", null);
            assertError("let:(a):(1)\nlet:(a):(2)", 0, 3, 6, "a second let of 'a': each name is defined once",
                    "the first 'a' is at line 2");
        }

        @Test
        void theUseOfABrokenLetIsNotAMistakeOfItsOwn() {
            assertError("let:(a):(1/0)\nsphere:(a|0|0):(1):(9|9|9)", 0, 2, 11,
                    "'1/0' is not a finite number: this part of it divides by 0", null);
        }

        @Test
        void aNestingTooDeepIsAMistakeNotACrash() {
            String deep = "(".repeat(150) + "1" + ")".repeat(150);
            assertError("sphere:(" + deep + "|0|0):(1):(9|9|9)", 0, 2, 9 + ExpressionParser.MAX_DEPTH,
                    "the expression is nested too deeply: more than " + ExpressionParser.MAX_DEPTH + " levels", null);
        }

        @Test
        void anExpressionOfTooManyOperatorsIsAMistakeNotACrash() {
            String sum = "1" + "+1".repeat(200_000);
            assertError("sphere:(" + sum + "|0|0):(1):(9|9|9)", 0, 2, 9 + 2 * ExpressionParser.MAX_OPERATORS + 1,
                    "the expression is too long: more than " + ExpressionParser.MAX_OPERATORS + " operators", null);
        }

        @Test
        void aWordThatIsNoNameKeepsTheMessageOfANumberMistyped() {
            assertError("sphere:(3|eight|-1):(2):(0|127|255)", 11, "expected a number, found 'eight'", Hints.NUMBER_FORMS);
        }
    }
}
