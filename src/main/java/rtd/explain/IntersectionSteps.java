package rtd.explain;

import rtd.geometry.Box;
import rtd.geometry.IGeometry;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.math.Ray;

/**
 * Step 2 of an explanation for one object (section 3.2.2): the numbers of its own intersection
 * test. A kind of object this class does not know shows only its test's answer.
 */
final class IntersectionSteps {

    private IntersectionSteps() {
    }

    /** Writes the test of {@code object} into {@code text}, its first line after {@code head}, and returns its t (NaN: no hit). */
    static float explain(Text text, String head, IGeometry object, Ray ray) {
        if (object instanceof Sphere sphere) {
            return SphereSteps.explain(text, head, sphere, ray);
        }
        if (object instanceof Plane plane) {
            return PlaneSteps.explain(text, head, plane, ray);
        }
        if (object instanceof Triangle triangle) {
            return TriangleSteps.explain(text, head, triangle, ray);
        }
        if (object instanceof Box box) {
            return BoxSteps.explain(text, head, box, ray);
        }
        float t = object.intersect(ray).t();
        text.hanging(head + object.kind() + ": its test gives t = " + Numbers.of(t) + (t >= 0 ? ": a hit" : ": no hit"));
        return t >= 0 ? t : Float.NaN;
    }
}
