package rtd.geometry;

import rtd.math.Ray;
import rtd.camera.ICamera;
import rtd.scene.Color;

/**
 * A geometric object of a scene (paper, section 4.2.2).
 *
 * <p>Each kind of object knows how to test itself against a ray, because that test differs
 * from shape to shape; the depth test that compares objects lives in {@link rtd.scene.Scene}.
 * A new shape (the paper names triangles) implements this interface.
 */
public interface IGeometry {

    /** The intersection test (section 3.2.2): where, if anywhere, the ray hits this object. */
    Intersection intersect(Ray ray);

    /** The flat colour the object paints the pixels whose ray it is nearest on. */
    Color color();

    /**
     * An axis-aligned box around this object that a bounding volume hierarchy can sort it by.
     *
     * <p>It must hold every point at which {@link #intersect} can report a hit for a ray of
     * {@code camera}, including the hits that single-precision rounding adds near the surface.
     * Otherwise the accelerated renderer could skip a hit that the paper's loop finds, and the
     * two pictures would differ.
     */
    BoundingBox bounds(ICamera camera);
}
