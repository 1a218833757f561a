package rtd.render;

import java.awt.image.BufferedImage;

/** A rendered image and the work that tracing it took. */
public record RenderResult(BufferedImage image, WorkCount work) {
}
