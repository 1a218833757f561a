package rtd.explain;

import java.util.List;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.DepthTest;
import rtd.scene.Scene;

/**
 * What rtd does for one pixel, in the paper's terms and order ({@code --explain X,Y}): ray generation (section 3.2.1,
 * Listing 4.1), the intersection test with every object in file order (section 3.2.2; spelt out for the first
 * {@value #LISTED} objects and every object the ray hits), the depth test (section 3.2.3, Listing 4.3) and the colour,
 * or with lights the tree of its shading. Every number is the renderer's own, told by each object's test as it
 * computes it ({@link rtd.geometry.TestObserver}), and the depth test is {@link Scene#nearestHit}'s {@link DepthTest}.
 */
public final class PixelExplanation {

    /** The objects whose tests are spelt out even if the ray misses them: the first ones of the file. */
    static final int LISTED = 20;

    private PixelExplanation() {
    }

    public static String of(Scene scene, int x, int y, int w, int h) {
        Text text = new Text();
        Ray ray = scene.camera().generateRay(x, y, w, h);
        RayGeneration.explain(text, scene.camera(), ray, x, y, w, h);
        text.blank();
        float[] t = intersectionTests(text, scene.objects(), ray);
        text.blank();
        int nearest = depthTest(text, scene.objects(), ray, t);
        text.blank();
        result(text, scene, ray, nearest);
        return text.toString();
    }

    private static float[] intersectionTests(Text text, List<IGeometry> objects, Ray ray) {
        text.line("2. Intersection tests, every object in file order (section 3.2.2: IGeometry.intersect)").in();
        if (objects.isEmpty()) {
            text.line("the scene has no objects");
        }
        float[] t = new float[objects.size()];
        int unlisted = 0;
        for (int i = 0; i < objects.size(); i++) {
            if (i >= LISTED && !objects.get(i).intersect(ray).happened()) {
                t[i] = Float.NaN; // a miss among thousands: counted below, not spelt out
                unlisted++;
                continue;
            }
            text.in();
            t[i] = IntersectionSteps.explain(text, "#" + (i + 1) + " ", objects.get(i), ray);
            text.out();
        }
        if (unlisted > 0) {
            text.in().line("… and " + unlisted + " more objects after #" + LISTED + " that the ray misses, each tested "
                    + "the same way (not listed; every object the ray hits is)").out();
        }
        text.out();
        return t;
    }

    /**
     * Listing 4.3's depth test on the hits, as {@link Scene#nearestHit}
     * runs it; returns the nearest object's place, or −1.
     */
    private static int depthTest(Text text, List<IGeometry> objects, Ray ray, float[] t) {
        text.line("3. Depth test (section 3.2.3, Listing 4.3: Scene.nearestHit): the hit nearest to O wins").in();
        float distance = Float.POSITIVE_INFINITY;
        int nearest = -1;
        for (int i = 0; i < objects.size(); i++) {
            if (!(t[i] >= 0)) {
                continue;
            }
            Vector3f point = ray.pointAt(t[i]);
            float current = DepthTest.distance(point, ray.origin());
            String where = "#" + (i + 1) + ": P = " + Numbers.of(point) + ", |P − O| = " + Numbers.of(current);
            if (DepthTest.nearer(current, i, distance, Math.max(nearest, 0))) {
                text.line(where + " < " + Numbers.of(distance) + ": the nearest so far");
                distance = current;
                nearest = i;
            } else {
                text.line(where + " ≥ " + Numbers.of(distance) + ": #" + (nearest + 1) + " stays the nearest"
                        + (current == distance ? " (a tie: the first in the file wins)" : ""));
            }
        }
        text.line(nearest < 0 ? "no object is hit" : "nearest: #" + (nearest + 1) + " " + objects.get(nearest).kind());
        text.out();
        return nearest;
    }

    private static void result(Text text, Scene scene, Ray ray, int nearest) {
        if (!scene.lights().isEmpty()) {
            ShadingExplanation.explain(text, scene, ray);
            return;
        }
        text.line("4. Result (section 3.2.3: the paper's flat colours, FlatShader)").in();
        Color colour;
        if (nearest < 0) {
            colour = scene.ambient();
            text.line("no hit: the background, the scene's ambient colour " + Numbers.of(colour));
        } else if (scene.objects().get(nearest).isPatterned()) {
            Hit hit = scene.nearestHit(ray);
            Vector3f under = hit.under(ray.direction(), hit.normal(ray.direction()));
            text.line("#" + (nearest + 1) + " " + hit.object().kind() + ", patterned: its colour at under = P − ε·N = "
                    + Numbers.of(under) + " (ε = " + Numbers.of(hit.lift()) + "), taken into the object's space");
            text.in();
            colour = hit.colour(ray.direction(), new PatternSteps(text));
            text.out();
        } else {
            colour = scene.objects().get(nearest).color();
            text.line("#" + (nearest + 1) + " " + scene.objects().get(nearest).kind() + ", colour "
                    + Numbers.of(colour));
        }
        text.line("pixel colour: " + Numbers.rgb(colour));
        text.out();
    }
}
