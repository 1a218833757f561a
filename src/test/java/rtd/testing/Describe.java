package rtd.testing;

import java.util.List;
import rtd.geometry.IGeometry;
import rtd.geometry.Triangle;

/**
 * Objects as text, for comparing scenes in tests: records compare by value already, but a
 * {@link Triangle} is a class (it keeps packed numbers), so two equal triangles are told apart
 * only by their corners, normal, smoothness, colour and finish.
 */
public final class Describe {

    private Describe() {
    }

    /** One object: a record as itself, a triangle by its fields. */
    public static String object(IGeometry object) {
        if (object instanceof Triangle t) {
            return "Triangle[" + t.corner(0) + ", " + t.corner(1) + ", " + t.corner(2) + ", n=" + t.planeNormal()
                    + ", smooth=" + t.isSmooth() + ", " + t.color() + ", " + t.material() + "]";
        }
        return object.toString();
    }

    /** Every object, in order. */
    public static List<String> objects(List<IGeometry> objects) {
        return objects.stream().map(Describe::object).toList();
    }
}
