package rtd.geometry;

import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * A shape whose colour group names a pattern (<i>The Ray Tracer Challenge</i>, chapter 10): the
 * shape's own test, normal, box and finish, and the pattern's colour at each point. A shape of
 * its own kind for every path: the engine sees an object it does not know, and tests it through
 * {@link #intersect}, which runs the shape's own test.
 *
 * @param shape   the shape, as the scene file gives it
 * @param pattern its colours
 */
public record Patterned(IGeometry shape, Pattern pattern) implements IGeometry {

    @Override
    public Intersection intersect(Ray ray) {
        return shape.intersect(ray);
    }

    @Override
    public Intersection intersect(Ray ray, TestObserver watch) {
        return shape.intersect(ray, watch);
    }

    @Override
    public Vector3f normalAt(Vector3f point) {
        return shape.normalAt(point);
    }

    @Override
    public Vector3f normalAt(Vector3f point, Vector3f direction) {
        return shape.normalAt(point, direction);
    }

    @Override
    public BoundingBox bounds() {
        return shape.bounds();
    }

    /** The pattern's first colour, a: what stands for the object where one colour must (a legend). */
    @Override
    public Color color() {
        return pattern.a();
    }

    @Override
    public boolean isPatterned() {
        return true;
    }

    /** The pattern's colour at {@code under}, a point in the shape's own space. */
    @Override
    public Color colorAt(Vector3f under, PatternObserver watch) {
        return pattern.colourAt(under, watch);
    }

    @Override
    public Material material() {
        return shape.material();
    }

    @Override
    public boolean isSolid() {
        return shape.isSolid();
    }

    @Override
    public String kind() {
        return shape.kind();
    }
}
