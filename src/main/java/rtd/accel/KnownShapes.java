package rtd.accel;

import java.util.List;
import rtd.geometry.Box;
import rtd.geometry.IGeometry;
import rtd.geometry.Plane;
import rtd.geometry.RayTriangle;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.math.Vector3f;

/**
 * What the engine knows of the book's shapes beyond their test and their box: how far a float
 * test may report a hit outside the box as the ray runs farther ({@link Rounding}), and when two
 * objects are twins that report the same hit for every ray. A shape it does not know gets the
 * safe answers: the widest rounding, and no twin. So a new shape is drawn right on every path
 * with only its test, normal and box. Not in the paper.
 */
final class KnownShapes {

    /**
     * How far a float intersection test may report a hit away from its object's box at most,
     * relative to the distance the ray has run: the widest rounding, for a shape without an
     * analysis of its own.
     */
    static final float ROUNDING_CONE = 1.1e-3f;
    /**
     * The lengths {@code |R|₁} of the directions {@link #roundingFrom} speaks of: a camera's rays
     * are about its focal length in pixels long. Far beyond these, a test's float products may
     * overflow or fall among the subnormal numbers, and its rounding is another matter.
     */
    static final double SHORTEST_DIRECTION = 1e-10;
    /** See {@link #SHORTEST_DIRECTION}. */
    static final double LONGEST_DIRECTION = 1e20;

    /** {@link #rounding} of a box and of a triangle, made once: a scene may have a million. */
    private static final Rounding BOX = Rounding.linear(1e-5f);
    private static final Rounding TRIANGLE = Rounding.linear(2 * RayTriangle.ALONG_THE_RAY);

    private KnownShapes() {
    }

    /**
     * How far {@code object}'s test may report a hit beside its box ({@link IGeometry#bounds})
     * as the ray runs a distance L: {@code linear·L + min(ROUNDING_CONE·L, quadratic·L²)}.
     *
     * <p>A sphere: in {@link Sphere#hit} the discriminant is a difference of two numbers as large
     * as {@code 4|R|²|O − M|²}. Following the standard error bounds of sums and products, the
     * float test hits where an exact test against a sphere of radius {@code r'} would, with
     * {@code r'² ≤ r² + δ} and {@code δ = 15u·D² + 6u·r²} (u the unit roundoff, D = |O − M|;
     * first order, with a quarter added). So the surface moves out by at most
     * {@code min(√δ, δ/2r) + 8u·D}. A hit at t has {@code D ≤ L + r'}, which bounds that by
     * {@code 1.062e-3·L + 1.74e-3·r} through the root, and by {@code (18.75u/2r)·L² + 2e-6·L + 1e-6·r}
     * through the quotient. The parts that grow with L are these; the rest the sphere's box holds
     * ({@link Sphere#bounds} grows it by {@code 2e-3·r}).
     *
     * <p>A box: the slab test's t has a relative error of a few units of the last place, far
     * less than {@code 1e-5·L}. A triangle: the plane's t and the hit point err by a few units of
     * the last place of the distance run, and the side tests allow up to
     * {@link RayTriangle#ALONG_THE_RAY} of the distance, summed over the axes (so up to √3 times).
     */
    static Rounding rounding(IGeometry object) {
        if (object instanceof Sphere sphere) {
            return new Rounding(2e-6f, (float) (18.75 * 0x1p-24 / (2.0 * sphere.radius()) * (1 + 1e-3)));
        }
        return object instanceof Box ? BOX : object instanceof Triangle ? TRIANGLE : Rounding.WIDEST;
    }

    /**
     * {@link #rounding} for the rays that leave {@code origin}, with a direction R of
     * {@link #SHORTEST_DIRECTION} ≤ |R|₁ ≤ {@link #LONGEST_DIRECTION}, for {@code object} whose
     * box is {@code box[at .. at+5]}: never more than {@link #rounding}. A triangle's test errs
     * less for a ray that meets it steeply, and the rays from one point meet it within a range of
     * angles ({@link TriangleRounding}).
     */
    static Rounding roundingFrom(IGeometry object, Vector3f origin, float[] box, int at) {
        if (object instanceof Triangle triangle) {
            double along = TriangleRounding.alongTheRayFrom(triangle, origin.x(), origin.y(), origin.z(), box, at);
            if (along < RayTriangle.ALONG_THE_RAY) {
                return Rounding.linear(Math.nextUp((float) (2 * along)));
            }
        }
        return rounding(object);
    }

    /**
     * A value that equals another object's exactly when the two report the same hit, to the last
     * bit, for every ray: the same shape in the same place, whatever its colour and finish. The
     * engine keeps only the first of such twins, which wins every tie. An object it does not
     * know is its own and only twin.
     */
    static Object twinKey(IGeometry object) {
        if (object instanceof Sphere sphere) {
            return List.of("sphere", sphere.center(), sphere.radius());
        }
        if (object instanceof Box box) {
            return List.of("box", box.min(), box.max());
        }
        if (object instanceof Triangle triangle) {
            return List.of("triangle", triangle.corner(0), triangle.corner(1), triangle.corner(2));
        }
        if (object instanceof Plane plane) {
            return List.of("plane", plane.point(), plane.normal());
        }
        return object;
    }

    /** Writes {@code object}'s box ({@link IGeometry#bounds}) to {@code into[at .. at+5]}: min x, y, z, max x, y, z. */
    static void putBox(IGeometry object, float[] into, int at) {
        if (object instanceof Triangle triangle) {
            triangle.putBounds(into, at); // no box object for each of a mesh's million triangles
        } else {
            object.bounds().put(into, at);
        }
    }
}
