package rtd.io;

import java.util.stream.Collectors;
import java.util.stream.IntStream;
import rtd.math.Vector3f;

/**
 * The rule of every group that sets a direction: a camera's view or a plane's normal, written as a direction
 * or, for a camera, {@code (at x|y|z)}, a point to look at (Part III, "A camera that looks at a point"); and
 * the axis of a solid between two end points (Part III, "More shapes"). Each must be a direction that is not
 * zero and whose squared length float can hold: float normalises it neither below the normal range nor when
 * it is infinite.
 */
final class Directions {

    private Directions() {
    }

    /** The three numbers of group {@code g} as a direction: finite, not zero, not too short or long for float. */
    static Vector3f direction(StatementValues v, int g, String zeroHelp) throws StatementError {
        Vector3f direction = v.vector(g);
        if (isZero(direction)) {
            throw v.errorAtValue(g, 0, "the " + v.meaning(g) + " must not be zero, found " + groupText(v, g), zeroHelp);
        }
        if (!computable(direction)) {
            throw v.errorAtValue(g, 0, "the " + v.meaning(g) + " " + groupText(v, g) + " is too "
                    + (tooLong(direction) ? "long" : "short") + " to compute with in float",
                    "only its direction matters: scale it to a length near 1");
        }
        return direction;
    }

    /** The point of group {@code g}, {@code (at x|y|z)}: the direction to it from {@code from} is one as above. */
    static Vector3f target(StatementValues v, int g, Vector3f from) throws StatementError {
        Vector3f target = v.vector(g);
        Vector3f direction = target.subtract(from);
        if (isZero(direction)) {
            throw v.errorAtValue(g, 0, "the camera cannot look at its own position " + groupText(v, g),
                    "give a point in front of the camera: (at " + StatementValues.plain(from.x()) + "|"
                            + StatementValues.plain(from.y()) + "|" + StatementValues.plain(from.z() - 1)
                            + ") looks along -z");
        }
        if (!computable(direction)) {
            throw v.errorAtValue(g, 0, "the point " + groupText(v, g) + " is too "
                    + (tooLong(direction) ? "far from" : "near")
                    + " the camera's position to compute the view direction in float",
                    "give a point at a distance near 1 to 1000 from the camera");
        }
        return target;
    }

    /** The axis of a solid from {@code first} to {@code second}, whose group {@code g} is the second end point. */
    static void axis(StatementValues v, Vector3f first, Vector3f second, int g, String shape, String help)
            throws StatementError {
        Vector3f axis = second.subtract(first);
        if (isZero(axis)) {
            throw v.errorAtGroup(g, "the " + shape + "'s two end points are the same point", help);
        }
        if (!computable(axis)) {
            throw v.errorAtGroup(g, "the " + shape + "'s end points are too " + (tooLong(axis) ? "far apart"
                    : "close together") + " to compute with in float",
                    "give end points a distance of about 1e-15 to 1e15 apart");
        }
    }

    /** Group {@code g} as written, "(0|0|0)"; "(at 0|0|0)" for a point to look at. */
    private static String groupText(StatementValues v, int g) {
        return IntStream.range(0, v.size(g)).mapToObj(k -> v.written(g, k))
                .collect(Collectors.joining("|", v.isTarget(g) ? "(at " : "(", ")"));
    }

    private static boolean isZero(Vector3f d) {
        return d.x() == 0 && d.y() == 0 && d.z() == 0;
    }

    private static boolean computable(Vector3f d) {
        return d.dot(d) >= Float.MIN_NORMAL && !tooLong(d);
    }

    private static boolean tooLong(Vector3f d) {
        return Float.isInfinite(d.dot(d));
    }
}
