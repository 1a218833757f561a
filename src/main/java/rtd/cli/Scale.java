package rtd.cli;

import java.util.Locale;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;
import rtd.camera.ICamera;
import rtd.camera.OrthographicCamera;
import rtd.scene.Scene;

/**
 * {@code --scale F}: the same view at another size. It multiplies the image's size, given by
 * {@code --width}/{@code --height} or their defaults, and the orthographic camera's zoom alike,
 * so that the picture shows the same part of the world: {@code --scale 0.25} makes the paper's
 * 1920×1080 at zoom 50 a 480×270 at zoom 12.5. The perspective camera needs no change: its field
 * of view spans the image's width at any size.
 *
 * <p>Without it, the paper's rule holds: the zoom is pixels per world unit, so a smaller image
 * shows less of the world.
 *
 * @param factor the factor, greater than 0; 1 leaves everything as it is
 */
record Scale(double factor) {

    /** No scaling. */
    static final Scale NONE = new Scale(1);

    /** {@code size} times the factor, rounded; 0 if that is less than half a pixel. */
    long times(int size) {
        return Math.round(size * factor);
    }

    /** {@code scene} with its camera scaled: the orthographic camera's zoom times the factor. */
    Scene of(Scene scene) {
        return factor == 1 ? scene : new Scene(scene.ambient(), camera(scene.camera()), scene.objects(), scene.lights());
    }

    private ICamera camera(ICamera camera) {
        if (camera instanceof OrthographicCamera orthographic) {
            return new OrthographicCamera(orthographic.position(), orthographic.direction(),
                    (float) (orthographic.zoom() * factor));
        }
        return camera; // the perspective camera's view depends on its field of view, not on the size
    }

    /** The factor as the user wrote it, without a needless ".0". */
    @Override
    public String toString() {
        return java.math.BigDecimal.valueOf(factor).stripTrailingZeros().toPlainString();
    }

    /** Reads {@code --scale}: a decimal number greater than 0, such as 0.25 or 2. */
    static final class Converter implements ITypeConverter<Scale> {
        @Override
        public Scale convert(String value) {
            String text = value.trim();
            try {
                // digits and a point only: no "NaN", "Infinity", hexadecimal or a type suffix like "2d"
                if (text.matches("[0-9]*\\.?[0-9]+([eE][-+]?[0-9]+)?|[0-9]+\\.")) {
                    double factor = Double.parseDouble(text);
                    if (factor > 0 && Double.isFinite(factor)) {
                        return new Scale(factor);
                    }
                }
            } catch (NumberFormatException e) {
                // answered below
            }
            throw new TypeConversionException(String.format(Locale.ROOT,
                    "'%s' is not a number greater than 0, such as 0.25 or 2", value));
        }
    }
}
