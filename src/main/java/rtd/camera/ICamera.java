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

    /**
     * If the rays of the pixels {@code [left, right) × [top, bottom)} of a {@code w × h} image all
     * share one direction, a {@link Beam} that holds them all, found without making each ray;
     * {@code null} if they do not, or if the camera cannot tell cheaply.
     */
    default Beam beam(int left, int top, int right, int bottom, int w, int h) {
        return null;
    }
}
