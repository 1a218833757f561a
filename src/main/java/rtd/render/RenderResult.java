package rtd.render;

/** A rendered picture and the work that tracing it took. */
public record RenderResult(Picture image, WorkCount work) {
}
