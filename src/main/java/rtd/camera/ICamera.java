package rtd.camera;

import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * A camera: it makes the ray for each pixel of the image, and so decides the projection
 * (paper, sections 3.2.1 and 4.3).
 *
 * <p>The paper's program has the orthographic camera; a perspective camera (section 3.2.1: one
 * origin, a direction per pixel) would be a second implementation.
 */
public interface ICamera {

    /**
     * Ray generation (section 3.2.1): the ray for pixel {@code (x, y)} of a {@code w × h} image,
     * x to the right and y downwards, both from 0.
     */
    Ray generateRay(int x, int y, int w, int h);

    /** The camera's position in the scene. */
    Vector3f position();

    /**
     * The largest distance from {@code point} to the origin of any ray of this camera that
     * passes within {@code reach} of {@code point}. A bounding volume hierarchy needs it to know
     * how large rounding errors can grow (see {@link rtd.geometry.IGeometry#bounds}).
     */
    float farthestOrigin(Vector3f point, float reach);
}
