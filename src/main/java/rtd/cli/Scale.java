package rtd.cli;

import java.math.BigDecimal;
import rtd.camera.OrthographicCamera;
import rtd.scene.Scene;

/**
 * {@code --scale F}: the same view at another size. It multiplies the image's size and the orthographic camera's
 * zoom (pixels per world unit) alike, so that the picture shows the same part of the world; the perspective
 * camera's field of view spans any width. {@code factor} is greater than 0.
 */
record Scale(double factor) {

    /** {@code size} times the factor, rounded; 0 if that is less than half a pixel. */
    long times(int size) {
        return Math.round(size * factor);
    }

    /** {@code scene} with the orthographic camera's zoom times the factor. */
    Scene of(Scene scene) {
        if (factor == 1 || !(scene.camera() instanceof OrthographicCamera camera)) {
            return scene;
        }
        float zoom = (float) (camera.zoom() * factor);
        OrthographicCamera scaled = camera.target() != null ? OrthographicCamera.lookingAt(camera.position(),
                camera.target(), zoom) : new OrthographicCamera(camera.position(), camera.direction(), zoom);
        return new Scene(scene.ambient(), scaled, scene.objects(), scene.lights());
    }

    @Override
    public String toString() {
        return BigDecimal.valueOf(factor).stripTrailingZeros().toPlainString();
    }
}
