package rtd.shade;

import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.geometry.PatternObserver;
import rtd.geometry.Material;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * What shading needs to know of the point a ray hit (Part II, "Light", step 2; <i>The Ray
 * Tracer Challenge</i>'s "prepare computations"): the point, the unit vector towards the eye,
 * the unit normal turned towards the eye, whether the ray is inside the object, and two points
 * just off the surface on either side, from which secondary rays leave so that they do not hit
 * the very surface they start on ("acne").
 *
 * @param ray      the ray that hit
 * @param hit      what it hit
 * @param eye      E = −R/|R|, towards where the ray came from
 * @param normal   N, the outward normal, or its opposite if the ray is inside
 * @param inside   whether the ray runs inside the object (N·E was negative)
 * @param over     P + ε·N, on the ray's side: where shadow and reflected rays leave
 * @param under    P − ε·N, beyond the surface: where refracted rays leave
 */
public record Surface(Ray ray, Hit hit, Vector3f eye, Vector3f normal, boolean inside, Vector3f over, Vector3f under) {

    /**
     * The surface at {@code hit}, a hit of {@code ray}; {@code ε = 1e-4·(1 + max(|Px|, |Py|,
     * |Pz|))} ({@link Hit#lift}), so that it stays above float's rounding of P however far P is from the origin.
     */
    public static Surface at(Ray ray, Hit hit) {
        Vector3f point = hit.point();
        Vector3f eye = ray.direction().normalize().inverse();
        Vector3f normal = hit.normal(ray.direction());
        boolean inside = normal.dot(eye) < 0;
        if (inside) {
            normal = normal.inverse();
        }
        float epsilon = hit.lift();
        Vector3f offset = normal.multiply(epsilon);
        return new Surface(ray, hit, eye, normal, inside, point.add(offset), point.subtract(offset));
    }

    /** The finish of the object hit. */
    public Material material() {
        return hit.object().material();
    }

    /**
     * The colour c of the object hit, as light (0 to 1): its flat colour, or a patterned object's
     * colour at {@link #under} ({@link Hit#colour} takes the same point).
     */
    public Rgb colour() {
        return colour(PatternObserver.NONE);
    }

    /** {@link #colour()}, telling {@code watch} how a pattern chose it ({@code --explain}). */
    public Rgb colour(PatternObserver watch) {
        IGeometry object = hit.object();
        Color colour = object.isPatterned() ? object.colorAt(under, watch) : object.color();
        return Rgb.of(colour);
    }
}
