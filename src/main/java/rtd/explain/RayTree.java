package rtd.explain;

import java.util.List;
import rtd.geometry.Hit;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.Scene;

/**
 * The rays of one pixel as data, for drawing them: the camera's ray to its hit, each shadow ray to its light if lit or
 * to its blocker, the reflected and refracted rays to their hits: the tree {@code --explain} writes out in words,
 * seen by the same observer of the renderer's own shader ({@link ShadingExplanation}), so every point is the picture's.
 *
 * @param segments the rays in the order the shader traces them, the camera's first
 */
public record RayTree(List<Segment> segments) {

    public enum Kind {
        CAMERA, REFLECTED, REFRACTED, SHADOW_LIT, SHADOW_BLOCKED
    }

    /**
     * One ray, from {@code from} to {@code to} (null: it hits nothing, and runs along {@code direction} for ever).
     *
     * @param depth 0 for the camera's ray and its shadow rays, 1 for the rays of its first bounce, and so on
     */
    public record Segment(Kind kind, Vector3f from, Vector3f to, Vector3f direction, int depth) {
    }

    public RayTree {
        segments = List.copyOf(segments);
    }

    /** The tree of pixel (x, y) of a {@code w × h} picture; without lights, the camera's ray alone. */
    public static RayTree of(Scene scene, int x, int y, int w, int h) {
        Ray ray = scene.camera().generateRay(x, y, w, h);
        return new RayTree(scene.lights().isEmpty() ? List.of(segment(Kind.CAMERA, ray, scene.nearestHit(ray), 0))
                : ShadingExplanation.rays(scene, ray));
    }

    static Segment segment(Kind kind, Ray ray, Hit hit, int depth) {
        return new Segment(kind, ray.origin(), hit == null ? null : hit.point(), ray.direction(), depth);
    }
}
