package rtd.io;

import rtd.math.Vector3f;

/**
 * The checks of a group that gives a direction: a camera's view or a plane's normal, written as a direction
 * or, for a camera, {@code (at x|y|z)}, a point to look at (Part III, "A camera that looks at a point").
 * Either must make a direction float can compute with.
 */
final class Directions {

    private Directions() {
    }

    /** The three numbers of group {@code g} as a direction: finite, not zero, not too short or long for float. */
    static Vector3f direction(StatementValues v, int g, String zeroHelp) throws StatementError {
        Vector3f direction = v.vector(g);
        if (direction.x() == 0 && direction.y() == 0 && direction.z() == 0) {
            throw v.errorAtValue(g, 0, "the " + v.meaning(g) + " must not be zero, found " + v.groupText(g), zeroHelp);
        }
        float squaredLength = direction.dot(direction);
        if (!(squaredLength >= Float.MIN_NORMAL) || Float.isInfinite(squaredLength)) {
            throw v.errorAtValue(g, 0, "the " + v.meaning(g) + " " + v.groupText(g) + " is too "
                    + (Float.isInfinite(squaredLength) ? "long" : "short") + " to compute with in float",
                    "only its direction matters: scale it to a length near 1");
        }
        return direction;
    }

    /**
     * The point of group {@code g}, written {@code (at x|y|z)}: the direction to it from {@code from} must be
     * neither zero nor too short or long for float.
     */
    static Vector3f target(StatementValues v, int g, Vector3f from) throws StatementError {
        Vector3f target = v.vector(g);
        Vector3f direction = target.subtract(from);
        float squaredLength = direction.dot(direction);
        if (direction.x() == 0 && direction.y() == 0 && direction.z() == 0) {
            throw v.errorAtValue(g, 0, "the camera cannot look at its own position " + v.groupText(g),
                    "give a point in front of the camera: (at " + plain(from.x()) + "|" + plain(from.y()) + "|"
                            + plain(from.z() - 1) + ") looks along -z");
        }
        if (!(squaredLength >= Float.MIN_NORMAL) || Float.isInfinite(squaredLength)) {
            String tooWhat = Float.isInfinite(squaredLength) ? "far from" : "near";
            throw v.errorAtValue(g, 0, "the point " + v.groupText(g) + " is too " + tooWhat
                    + " the camera's position to compute the view direction in float",
                    "give a point at a distance near 1 to 1000 from the camera");
        }
        return target;
    }

    /** A number for a hint, without a trailing ".0": 3, -0.5. */
    private static String plain(float value) {
        return value == Math.rint(value) ? String.valueOf((long) value) : String.valueOf(value);
    }
}
