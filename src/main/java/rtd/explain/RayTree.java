package rtd.explain;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import rtd.geometry.Hit;
import rtd.image.Rgb;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.LinearTracer;
import rtd.scene.Light;
import rtd.scene.Scene;
import rtd.shade.LightTerms;
import rtd.shade.ShadingObserver;
import rtd.shade.Snell;
import rtd.shade.WhittedShader;

/**
 * The rays of one pixel as data, for drawing them: the camera's ray to its hit, each shadow ray towards its light (to
 * the light if lit, to the object that blocks it if not), and the reflected and refracted rays to their hits, down to
 * the last bounce. It is the tree {@code --explain} writes out in words (its step 4), taken from the same observer of
 * the renderer's own shader ({@link ShadingObserver}), so every point is the picture's.
 *
 * @param segments the rays in the order the shader traces them, the camera's first
 */
public record RayTree(List<Segment> segments) {

    public enum Kind {
        CAMERA, REFLECTED, REFRACTED, SHADOW_LIT, SHADOW_BLOCKED
    }

    /**
     * One ray of the tree, from {@code from} to {@code to}; a ray that hits nothing has no end ({@code to} null) and
     * runs along {@code direction} for ever.
     *
     * @param depth 0 for the camera's ray and its shadow rays, 1 for the rays of its first bounce, and so on
     */
    public record Segment(Kind kind, Vector3f from, Vector3f to, Vector3f direction, int depth) {
    }

    public RayTree {
        segments = List.copyOf(segments);
    }

    /**
     * The tree of pixel (x, y) of a {@code w × h} picture of {@code scene}: with lights, as the shader follows it;
     * without, the camera's ray alone, as the paper's flat colours need no other.
     */
    public static RayTree of(Scene scene, int x, int y, int w, int h) {
        Ray ray = scene.camera().generateRay(x, y, w, h);
        if (scene.lights().isEmpty()) {
            Hit hit = scene.nearestHit(ray);
            return new RayTree(List.of(segment(Kind.CAMERA, ray, hit, 0)));
        }
        Collector collector = new Collector();
        new WhittedShader(scene, new LinearTracer(scene), collector).colourAt(ray, WhittedShader.BOUNCES);
        return new RayTree(collector.segments);
    }

    private static Segment segment(Kind kind, Ray ray, Hit hit, int depth) {
        return new Segment(kind, ray.origin(), hit == null ? null : hit.point(), ray.direction(), depth);
    }

    /** Writes down each ray as the shader announces it. */
    private static final class Collector implements ShadingObserver {
        final List<Segment> segments = new ArrayList<>();
        /** The kind of each open ray, innermost first. */
        private final Deque<Kind> open = new ArrayDeque<>();
        private Kind next = Kind.CAMERA;
        private Ray shadowRay;
        private Hit blocker;

        @Override
        public void ray(Ray ray, Hit hit, int remaining) {
            segments.add(segment(next, ray, hit, open.size()));
            open.push(next);
        }

        @Override
        public void shadowRay(Light light, Ray ray, Hit hit, float lightDistance) {
            shadowRay = ray;
            blocker = hit;
        }

        @Override
        public void light(Light light, boolean shadowed, LightTerms terms) {
            if (shadowRay == null) {
                return; // the shader decided without a shadow ray
            }
            int depth = open.size() - 1;
            segments.add(new Segment(shadowed ? Kind.SHADOW_BLOCKED : Kind.SHADOW_LIT, shadowRay.origin(),
                    shadowed ? blocker.point() : light.position(), shadowRay.direction(), depth));
            shadowRay = null;
        }

        @Override
        public void reflected(Ray ray) {
            next = Kind.REFLECTED;
        }

        @Override
        public void refracted(Ray ray, Snell snell) {
            next = Kind.REFRACTED;
        }

        @Override
        public void colour(Rgb colour) {
            open.pop();
        }
    }
}
