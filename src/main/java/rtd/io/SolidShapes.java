package rtd.io;

import rtd.geometry.Cone;
import rtd.geometry.Cylinder;
import rtd.math.Vector3f;
import rtd.scene.AreaLight;

/**
 * The builders of the solids between two end points (Part III, "More shapes"): a cylinder of
 * radius greater than 0, a cone whose radii are at least 0 and not both 0, each between two
 * different end points; and the rule of an area light's samples ("Area lights").
 */
final class SolidShapes {

    private SolidShapes() {
    }

    /** {@code cylinder:(x1|y1|z1):(x2|y2|z2):(r):(R|G|B)}. */
    static Cylinder cylinder(StatementValues v) throws StatementError {
        Vector3f first = v.vector(0);
        Vector3f second = v.vector(1);
        float radius = v.positive(2);
        Directions.axis(v, first, second, 1, "cylinder", "a cylinder runs from one end point to another, such as (0|0|0) to (0|2|0)");
        return new Cylinder(first, second, radius, v.colour(3), v.material());
    }

    /** {@code cone:(x1|y1|z1):(r1):(x2|y2|z2):(r2):(R|G|B)}. */
    static Cone cone(StatementValues v) throws StatementError {
        Vector3f first = v.vector(0);
        float firstRadius = atLeastZero(v, 1, "first radius");
        Vector3f second = v.vector(2);
        float secondRadius = atLeastZero(v, 3, "second radius");
        if (firstRadius == 0 && secondRadius == 0) {
            throw v.errorAtValue(3, 0, "the cone's radii are both 0, so it has no volume",
                    "give one end a radius greater than 0: cone:(0|0|0):(1):(0|2|0):(0) is a cone with its apex up");
        }
        Directions.axis(v, first, second, 2, "cone", "a cone runs from one end point to another, such as (0|0|0) to (0|2|0)");
        return new Cone(first, firstRadius, second, secondRadius, v.colour(4), v.material());
    }

    /** The one number of group {@code g}, finite and at least 0: a cone's radius. */
    private static float atLeastZero(StatementValues v, int g, String name) throws StatementError {
        float value = v.number(g, 0);
        if (value >= 0) {
            return value;
        }
        throw v.errorAtValue(g, 0, "the " + name + " must be at least 0, found " + v.written(g, 0),
                "without its minus sign: " + v.written(g, 0).substring(1));
    }

    /**
     * Number {@code k} of group {@code g}, a whole number from 1 to {@link AreaLight#MOST_SAMPLES}:
     * an area light's samples along one edge.
     */
    static int samples(StatementValues v, int g, int k, String name) throws StatementError {
        float value = v.number(g, k);
        if (value >= 1 && value <= AreaLight.MOST_SAMPLES && value == Math.rint(value)) {
            return (int) value;
        }
        throw v.errorAtValue(g, k, "the " + name + " must be a whole number from 1 to " + AreaLight.MOST_SAMPLES
                + ", found " + v.written(g, k), "more samples make a softer shadow and cost more shadow rays; 4|4 is a good start");
    }
}
