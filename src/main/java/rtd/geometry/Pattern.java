package rtd.geometry;

import java.util.Locale;
import rtd.image.Color;
import rtd.math.Matrix4;
import rtd.math.Vector3f;

/**
 * A pattern of two colours a and b in space (<i>The Ray Tracer Challenge</i>, chapter 10): which
 * colour a point of an object's surface shows. The four rules, each written once, in
 * {@link #colourAt(Vector3f, PatternObserver)}, for the point (x, y, z) in the pattern's space:
 * <ul>
 * <li>stripes: a if floor(x) is even, else b;</li>
 * <li>gradient: a + (b − a)·(x − floor(x)), each channel rounded to a whole number (½ up);</li>
 * <li>rings: a if floor(√(x² + z²)) is even, else b;</li>
 * <li>checker: a if floor(x) + floor(y) + floor(z) is even, else b.</li>
 * </ul>
 * The point comes in object space (a {@link Patterned} object passes it on); the pattern's own
 * transform takes it into the pattern's space first (its inverse), in double.
 */
public final class Pattern {

    /** The four rules. */
    public enum Kind {
        STRIPES, GRADIENT, RINGS, CHECKER;

        /** The name the scene file writes: "stripes", "checker". */
        public String word() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    private final Kind kind;
    private final Color a;
    private final Color b;
    private final Matrix4 transform;
    private final Matrix4 inverse;

    /**
     * The pattern of {@code kind} in colours a and b, placed by {@code transform} ({@link Matrix4#IDENTITY}: as it is).
     */
    public Pattern(Kind kind, Color a, Color b, Matrix4 transform) {
        this.kind = kind;
        this.a = a;
        this.b = b;
        this.transform = transform;
        this.inverse = transform.inverse();
    }

    public Kind kind() {
        return kind;
    }

    public Color a() {
        return a;
    }

    public Color b() {
        return b;
    }

    /** Where the pattern lies in the object's space. */
    public Matrix4 transform() {
        return transform;
    }

    /** The colour at {@code point}, a point in the object's space. */
    public Color colourAt(Vector3f point) {
        return colourAt(point, PatternObserver.NONE);
    }

    /** {@link #colourAt(Vector3f)}, telling {@code watch} the point in the pattern's space and the rule's number. */
    public Color colourAt(Vector3f point, PatternObserver watch) {
        double[] p = new double[3];
        inverse.point(point.x(), point.y(), point.z(), p);
        double x = p[0];
        double y = p[1];
        double z = p[2];
        double value = switch (kind) {
            case STRIPES -> Math.floor(x);
            case GRADIENT -> x - Math.floor(x);
            case RINGS -> Math.floor(Math.sqrt(x * x + z * z));
            case CHECKER -> Math.floor(x) + Math.floor(y) + Math.floor(z);
        };
        Color colour = kind == Kind.GRADIENT ? blend(value) : isEven(value) ? a : b;
        watch.pattern(this, x, y, z, value, colour);
        return colour;
    }

    /** Whether a whole number (as a double) is even; −1 is odd, −2 even. */
    public static boolean isEven(double whole) {
        return whole % 2 == 0;
    }

    /** a + (b − a)·f, channel by channel, rounded to whole numbers (½ up), as the scene file's colours are. */
    private Color blend(double f) {
        return new Color(channel(a.red(), b.red(), f), channel(a.green(), b.green(), f),
                channel(a.blue(), b.blue(), f));
    }

    private static int channel(int from, int to, double f) {
        return (int) Math.floor(from + (to - from) * f + 0.5);
    }
}
