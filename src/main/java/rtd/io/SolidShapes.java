package rtd.io;

import rtd.geometry.Cone;
import rtd.geometry.Cylinder;
import rtd.math.Vector3f;

/**
 * The builders of the solids between two end points (Part III, "More shapes"): a cylinder of
 * radius greater than 0, a cone whose radii are at least 0 and not both 0, each between two
 * different end points.
 */
final class SolidShapes {

    private SolidShapes() {
    }

    /** {@code cylinder:(x1|y1|z1):(x2|y2|z2):(r):(R|G|B)}. */
    static Cylinder cylinder(StatementValues v) throws StatementError {
        Vector3f first = v.vector(0);
        Vector3f second = v.vector(1);
        float radius = v.positive(2);
        ends(v, first, second, 1, "cylinder", "a cylinder runs from one end point to another, such as (0|0|0) to (0|2|0)");
        return new Cylinder(first, second, radius, v.colour(3), v.material());
    }

    /** {@code cone:(x1|y1|z1):(r1):(x2|y2|z2):(r2):(R|G|B)}. */
    static Cone cone(StatementValues v) throws StatementError {
        Vector3f first = v.vector(0);
        float firstRadius = v.atLeastZero(1);
        Vector3f second = v.vector(2);
        float secondRadius = v.atLeastZero(3);
        if (firstRadius == 0 && secondRadius == 0) {
            throw v.errorAtValue(3, 0, "the cone's radii are both 0, so it has no volume",
                    "give one end a radius greater than 0: cone:(0|0|0):(1):(0|2|0):(0) is a cone with its apex up");
        }
        ends(v, first, second, 2, "cone", "a cone runs from one end point to another, such as (0|0|0) to (0|2|0)");
        return new Cone(first, firstRadius, second, secondRadius, v.colour(4), v.material());
    }

    /** The end points must differ, by a distance whose square float can hold. */
    private static void ends(StatementValues v, Vector3f first, Vector3f second, int g, String shape, String help)
            throws StatementError {
        Vector3f axis = second.subtract(first);
        float squaredLength = axis.dot(axis);
        if (axis.x() == 0 && axis.y() == 0 && axis.z() == 0) {
            throw v.errorAtGroup(g, "the " + shape + "'s two end points are the same point", help);
        }
        if (!(squaredLength >= Float.MIN_NORMAL) || Float.isInfinite(squaredLength)) {
            throw v.errorAtGroup(g, "the " + shape + "'s end points are too " + (Float.isInfinite(squaredLength)
                    ? "far apart" : "close together") + " to compute with in float",
                    "give end points a distance of about 1e-15 to 1e15 apart");
        }
    }
}
