package rtd.window;

import rtd.camera.ICamera;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * A coarse pass's camera: pixel (x, y) of the small picture of a {@code block}-pixel grid is the ray of pixel
 * {@code (x·block, y·block)} of the full {@code width × height} picture, the top left pixel of its block. So every
 * ray of a coarse pass is one of the final picture's own rays, made by the scene's camera (one equation, one place),
 * and a block shows the colour its top left pixel will have.
 */
record BlockCamera(ICamera full, int block, int width, int height) implements ICamera {

    @Override
    public Ray generateRay(int x, int y, int w, int h) {
        return full.generateRay(x * block, y * block, width, height);
    }

    @Override
    public Ray generateRay(float x, float y, int w, int h) {
        return full.generateRay(x * block, y * block, width, height);
    }

    @Override
    public Vector3f position() {
        return full.position();
    }
}
