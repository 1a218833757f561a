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

    /**
     * {@link #generateRay(float, float, int, int)} as numbers: the origin's x, y, z, then the
     * direction's, into {@code into[at .. at + 5]}, for renderers that keep rays as numbers.
     */
    default void putRay(float x, float y, int w, int h, float[] into, int at) {
        Ray ray = generateRay(x, y, w, h);
        into[at] = ray.origin().x();
        into[at + 1] = ray.origin().y();
        into[at + 2] = ray.origin().z();
        into[at + 3] = ray.direction().x();
        into[at + 4] = ray.direction().y();
        into[at + 5] = ray.direction().z();
    }

    /** The camera's position in the scene. */
    Vector3f position();
}
