package rtd.render;

import rtd.image.Picture;

/** A rendered picture and the work that tracing it took. */
public record RenderResult(Picture image, WorkCount work) {
}
