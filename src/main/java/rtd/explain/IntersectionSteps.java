package rtd.explain;

import rtd.geometry.Box;
import rtd.geometry.Cone;
import rtd.geometry.Cylinder;
import rtd.geometry.IGeometry;
import rtd.geometry.Patterned;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.TestObserver;
import rtd.geometry.Transformed;
import rtd.geometry.Triangle;
import rtd.math.Ray;

/**
 * Step 2 of an explanation for one object (section 3.2.2): the object's own intersection test,
 * run with an observer that writes each of its numbers. A kind of object this class does not
 * know shows only its test's answer.
 */
final class IntersectionSteps {

    private IntersectionSteps() {
    }

    /** Runs the test of {@code object}, writing it into {@code text}, its first line after {@code head}; returns its t (NaN: no hit). */
    static float explain(Text text, String head, IGeometry object, Ray ray) {
        TestObserver steps = observerOf(text, head, object);
        float t = object.intersect(ray, steps).t();
        verdict(text, head, object, steps, t);
        return t >= 0 ? t : Float.NaN;
    }

    /** The last line of a test's steps: its answer, where its steps do not say it. */
    private static void verdict(Text text, String head, IGeometry object, TestObserver steps, float t) {
        if (steps instanceof TransformedSteps transformed) {
            IGeometry shape = ((Transformed) object).shape();
            verdict(text, "", shape instanceof Patterned p ? p.shape() : shape, transformed.inner(), t);
            transformed.done(t);
        } else if (steps instanceof BoxSteps box) {
            box.verdict(t);
        } else if (steps instanceof TriangleSteps triangle) {
            triangle.verdict(t);
        } else if (steps == TestObserver.NONE) {
            text.hanging(head + object.kind() + ": its test gives t = " + Numbers.of(t) + (t >= 0 ? ": a hit" : ": no hit"));
        }
    }

    private static TestObserver observerOf(Text text, String head, IGeometry object) {
        if (object instanceof Patterned patterned) {
            return observerOf(text, head, patterned.shape()); // the shape's own test
        }
        if (object instanceof Transformed transformed) {
            return new TransformedSteps(text, head, transformed, inner -> observerOf(inner, "", transformed.shape()));
        }
        if (object instanceof Sphere sphere) {
            return new SphereSteps(text, head, sphere);
        }
        if (object instanceof Plane plane) {
            return new PlaneSteps(text, head, plane);
        }
        if (object instanceof Triangle triangle) {
            return new TriangleSteps(text, head, triangle);
        }
        if (object instanceof Box box) {
            return new BoxSteps(text, head, box);
        }
        if (object instanceof Cylinder cylinder) {
            return new CylinderSteps(text, head, cylinder);
        }
        if (object instanceof Cone cone) {
            return new ConeSteps(text, head, cone);
        }
        return TestObserver.NONE;
    }
}
