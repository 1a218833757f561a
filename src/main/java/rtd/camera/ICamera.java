package rtd.camera;

import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * A camera: it makes the ray for each pixel of the image, and so decides the projection
 * (paper, sections 3.2.1 and 4.3).
 *
 * <p>The paper's program has the {@link OrthographicCamera}; section 3.2.1 describes the
 * {@link PerspectiveCamera} beside it (one origin, a direction per pixel). A new projection
 * implements this interface.
 */
public interface ICamera {

    /**
     * Ray generation (section 3.2.1): the ray for pixel {@code (x, y)} of a {@code w × h} image,
     * x to the right and y downwards, both from 0. It leaves the pixel's corner.
     */
    Ray generateRay(int x, int y, int w, int h);

    /**
     * The ray through the point {@code (x, y)} of the image, where a whole number is a pixel's
     * corner as in {@link #generateRay(int, int, int, int)}, which this equals there; fractions
     * reach points inside a pixel (anti-aliasing takes several per pixel).
     */
    Ray generateRay(float x, float y, int w, int h);

    /** The camera's position in the scene. */
    Vector3f position();
}
