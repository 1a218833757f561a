package rtd.shade;

import rtd.geometry.Hit;
import rtd.geometry.PatternObserver;
import rtd.image.Rgb;
import rtd.math.Ray;
import rtd.scene.Light;

/**
 * Watches {@link WhittedShader} at work, for {@code --explain}: it is told each step's numbers
 * as the shader computes them (Part II, "Light", steps 1 to 6), so that an explanation shows
 * the very numbers of the picture, not a second computation of them. Rendering uses
 * {@link #NONE}, which does nothing.
 *
 * <p>The calls nest as the shader recurses: {@link #ray} opens a ray and {@link #colour} closes
 * it; between them come the surface, each light, and the reflected and refracted rays, each
 * announced by {@link #reflected} or {@link #refracted} and then opened by its own {@link #ray}.
 */
public interface ShadingObserver {

    /** Watches nothing: the renderer's observer. */
    ShadingObserver NONE = new ShadingObserver() {
    };

    /** {@code ray} hits {@code hit} ({@code null}: nothing), with {@code remaining} bounces left. */
    default void ray(Ray ray, Hit hit, int remaining) {
    }

    /** What the shader knows of the hit point (step 2). */
    default void surface(Surface surface) {
    }

    /** Who watches a patterned surface's pattern choose its colour c (step 2); nobody by default. */
    default PatternObserver patterns() {
        return PatternObserver.NONE;
    }

    /**
     * The shadow ray towards {@code light} hit {@code blocker}
     * ({@code null}: nothing); the light is {@code lightDistance} away.
     */
    default void shadowRay(Light light, Ray shadowRay, Hit blocker, float lightDistance) {
    }

    /** {@code light} gives the point these terms (step 3). */
    default void light(Light light, boolean shadowed, LightTerms terms) {
    }

    /** A reflected ray leaves (step 4); its shading follows. */
    default void reflected(Ray ray) {
    }

    /** A refracted ray leaves (step 5), bent as {@code snell} says; its shading follows. */
    default void refracted(Ray ray, Snell snell) {
    }

    /** No refracted ray: the light is totally reflected inside (step 5), as {@code snell} says. */
    default void totalInternalReflection(Snell snell) {
    }

    /** Schlick's reflectance mixes reflection and refraction (step 6). */
    default void fresnel(float reflectance) {
    }

    /** The ray opened by the last unclosed {@link #ray} sees {@code colour}. */
    default void colour(Rgb colour) {
    }
}
