package rtd.shade;

import java.util.Map;
import java.util.TreeMap;
import rtd.geometry.Hit;
import rtd.geometry.Material;
import rtd.image.Rgb;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.render.Shader;
import rtd.render.Tracer;
import rtd.scene.Light;
import rtd.scene.Scene;

/**
 * Whitted ray tracing: the colour a ray sees, with lights, shadows, mirror reflection and
 * refraction (Part II, "Light"; the model of <i>The Ray Tracer Challenge</i>). The paper stops
 * at the camera's rays and flat colours and names these secondary rays as the way on (sections
 * 3.2.3 and 5); this is that next chapter.
 *
 * <p>{@link #shade} is the one place where a ray's colour is decided: the surface lit by each
 * light ({@link Lighting}), then what a mirror shows ({@link #reflected}), then what shows
 * through ({@link #refracted}), mixed by Fresnel's law where a surface does both. Every ray,
 * secondary or not, asks the same question of the same {@link Tracer}: what does it hit?
 *
 * <p>The steps that the other classes of this package and {@link ShadingObserver} name by number:
 * <ol>
 * <li>a ray that hits nothing shows the background ({@link #shade});
 * <li>what shading needs of the hit point: P, N, E and the points lifted off the surface ({@link Surface});
 * <li>each light's ambient, diffuse and specular terms, after a shadow ray ({@link Lighting});
 * <li>what a mirror shows ({@link #reflected});
 * <li>what shows through, by Snell's law ({@link Snell});
 * <li>reflection and refraction mixed by Schlick's approximation ({@link Snell#reflectance}).
 * </ol>
 */
public final class WhittedShader implements Shader {

    /** How many times a ray may be reflected or refracted: the camera's ray starts with this many. */
    public static final int BOUNCES = 5;

    private final Scene scene;
    /**
     * The scene's lights, as an array: the loop over them runs for every point lit, and a loop
     * over an array makes no iterator object there.
     */
    private final Light[] lights;
    private final Tracer tracer;
    private final Rgb background;
    private final ShadingObserver observer;
    private long shadowRays;
    private long reflectedRays;
    private long refractedRays;

    /** A shader for {@code scene} that follows secondary rays with {@code tracer} (one per thread). */
    public WhittedShader(Scene scene, Tracer tracer) {
        this(scene, tracer, ShadingObserver.NONE);
    }

    /** A shader that tells {@code observer} each step's numbers ({@code --explain}). */
    public WhittedShader(Scene scene, Tracer tracer, ShadingObserver observer) {
        this.scene = scene;
        this.lights = scene.lights().toArray(Light[]::new);
        this.tracer = tracer;
        this.background = Rgb.of(scene.ambient());
        this.observer = observer;
    }

    @Override
    public Rgb colour(RayBundle rays, HitBuffer hits, int i) {
        Ray ray = rays.ray(i);
        return shade(ray, hits.hit(i, ray, scene.objects()), BOUNCES);
    }

    /** The colour {@code ray} sees, following at most {@code remaining} more bounces. */
    public Rgb colourAt(Ray ray, int remaining) {
        return shade(ray, tracer.nearestHit(ray), remaining);
    }

    /**
     * Step 1 to 6: nothing hit shows the background; else the surface's own light, plus what
     * its mirror reflects, plus what shows through it.
     */
    Rgb shade(Ray ray, Hit hit, int remaining) {
        observer.ray(ray, hit, remaining);
        Rgb colour = hit == null ? background : shadeSurface(ray, hit, remaining);
        observer.colour(colour);
        return colour;
    }

    private Rgb shadeSurface(Ray ray, Hit hit, int remaining) {
        Surface surface = Surface.at(ray, hit);
        observer.surface(surface);
        Rgb lit = lit(surface);
        Rgb reflected = reflected(surface, remaining);
        Rgb refracted = refracted(surface, remaining);
        Material material = surface.material();
        if (material.reflective() > 0 && material.transparency() > 0) {
            float reflectance = Snell.at(surface).reflectance();
            observer.fresnel(reflectance);
            return lit.plus(reflected.times(reflectance)).plus(refracted.times(1 - reflectance));
        }
        return lit.plus(reflected).plus(refracted);
    }

    /** Step 3: the light of every light at the point, or only its ambient share where the light is shadowed. */
    private Rgb lit(Surface surface) {
        Rgb sum = Rgb.BLACK;
        Rgb colour = surface.colour(observer.patterns()); // c, the same for every light
        for (Light light : lights) {
            // a light behind the surface gives only its ambient part: no shadow ray needed to know
            boolean shadow = facesTheLight(surface, light) && isShadowed(surface.over(), light);
            LightTerms terms = Lighting.terms(surface.material(), colour, light, surface.over(), surface.eye(),
                    surface.normal(), shadow);
            observer.light(light, shadow, terms);
            sum = sum.plus(terms.sum());
        }
        return sum;
    }

    /**
     * Whether the light is in front of the surface ({@code N·L > 0}),
     * where its shadow ray matters; always while explaining.
     */
    private boolean facesTheLight(Surface surface, Light light) {
        return observer != ShadingObserver.NONE
                || light.position().subtract(surface.over()).normalize().dot(surface.normal()) > 0;
    }

    /**
     * Whether a ray from {@code point} towards the light hits any object nearer than the light,
     * by more than the light's {@link Light#clearance}: the ray ends ε short of the light, as it
     * starts ε above the surface, so that a light placed on a surface lights what it faces.
     */
    boolean isShadowed(Vector3f point, Light light) {
        shadowRays++;
        Vector3f toLight = light.position().subtract(point);
        Ray shadowRay = new Ray(point, toLight);
        float distance = toLight.magnitude() - light.clearance();
        if (observer == ShadingObserver.NONE) {
            return tracer.blocked(shadowRay, distance); // any object before the light will do
        }
        Hit blocker = tracer.nearestHit(shadowRay); // an explanation names the nearest
        observer.shadowRay(light, shadowRay, blocker, distance);
        return blocker != null && blocker.distance() < distance;
    }

    /**
     * Step 4: {@code reflective · shade(ray from over along R − 2(R·N)N)}; black for a matt surface or the last bounce.
     */
    private Rgb reflected(Surface surface, int remaining) {
        float reflective = surface.material().reflective();
        if (reflective <= 0 || remaining <= 0) {
            return Rgb.BLACK;
        }
        reflectedRays++;
        Vector3f direction = surface.ray().direction();
        Vector3f normal = surface.normal();
        Vector3f mirrored = direction.subtract(normal.multiply(2 * direction.dot(normal)));
        Ray ray = new Ray(surface.over(), mirrored);
        observer.reflected(ray);
        return colourAt(ray, remaining - 1).times(reflective);
    }

    /**
     * Step 5: Snell's law. Entering, from air (1) into the object's ior; leaving, the other way.
     * Past the critical angle the light is totally reflected inside, and nothing comes through:
     * black.
     */
    private Rgb refracted(Surface surface, int remaining) {
        float transparency = surface.material().transparency();
        if (transparency <= 0 || remaining <= 0) {
            return Rgb.BLACK;
        }
        Snell snell = Snell.at(surface);
        if (snell.totalInternalReflection()) {
            observer.totalInternalReflection(snell);
            return Rgb.BLACK;
        }
        refractedRays++;
        Vector3f direction = surface.normal().multiply(snell.ratio() * snell.cosIncidence() - snell.cosTransmitted())
                .subtract(surface.eye().multiply(snell.ratio()));
        Ray ray = new Ray(surface.under(), direction);
        observer.refracted(ray, snell);
        return colourAt(ray, remaining - 1).times(transparency);
    }

    @Override
    public Map<String, Long> secondaryRays() {
        Map<String, Long> rays = new TreeMap<>();
        rays.put("shadow", shadowRays);
        rays.put("reflected", reflectedRays);
        rays.put("refracted", refractedRays);
        return rays;
    }
}
