package rtd.explain;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Set;
import rtd.explain.RayTree.Kind;
import rtd.explain.RayTree.Segment;
import rtd.geometry.Hit;
import rtd.geometry.Material;
import rtd.geometry.PatternObserver;
import rtd.geometry.Triangle;
import rtd.image.Rgb;
import rtd.math.Ray;
import rtd.render.LinearTracer;
import rtd.scene.AreaLight;
import rtd.scene.Light;
import rtd.scene.Scene;
import rtd.shade.LightTerms;
import rtd.shade.ShadingObserver;
import rtd.shade.Snell;
import rtd.shade.Surface;
import rtd.shade.WhittedShader;

/**
 * Step 4 of an explanation for a scene with lights (Part II, "Light"; beyond the paper's flat colours): the tree of
 * what {@link WhittedShader} computes for the camera's ray, each light's ambient, diffuse and specular terms, the
 * shadow ray's verdict, and the reflected and refracted rays, indented, down to the last bounce; and the same tree as
 * the {@link RayTree} of its rays. It watches the renderer's own shader ({@link ShadingObserver}) with the paper's
 * loop as its tracer, so every number and point is the picture's.
 */
final class ShadingExplanation implements ShadingObserver {

    /**
     * One open ray: its finish (null: it hit nothing), whether its surface has a back, what was said, and the parts of
     * its colour (step 6's sum) as they come: the lights' terms, what the reflected and refracted rays see (null:
     * none), which of the two the next ray is, and Schlick's reflectance where it mixes them (NaN otherwise).
     */
    private static final class Frame {
        Material material;
        boolean hasBack;
        boolean reflectionSaid;
        boolean refractionSaid;
        Rgb surface = Rgb.BLACK;
        Rgb reflection;
        Rgb refraction;
        boolean childIsReflection;
        float reflectance = Float.NaN;
    }

    private final Text text;
    private final Deque<Frame> open = new ArrayDeque<>();
    private final List<Segment> segments = new ArrayList<>();
    private Ray shadowRay;
    private Hit blocker;
    private float lightDistance;
    private int lightNumber;
    /** The samples of the area light being explained seen so far, how many of them are lit, and their terms summed. */
    private int samplesSeen;
    private int samplesLit;
    private Rgb areaSum = Rgb.BLACK;

    private ShadingExplanation(Text text) {
        this.text = text;
    }

    /** The rays the shader follows for {@code ray} in {@code scene}, in the order it traces them. */
    static List<Segment> rays(Scene scene, Ray ray) {
        ShadingExplanation tree = new ShadingExplanation(new Text());
        tree.shade(scene, ray);
        return tree.segments;
    }

    private Rgb shade(Scene scene, Ray ray) {
        return new WhittedShader(scene, new LinearTracer(scene), this).colourAt(ray, WhittedShader.BOUNCES);
    }

    /** Writes the shading of {@code ray} in {@code scene} into {@code text}, ending with the pixel's colour. */
    static void explain(Text text, Scene scene, Ray ray) {
        text.line("4. Result, shaded (beyond the paper, which stops at flat colours: WhittedShader.shade)").in();
        Set<AreaLight> areas = Collections.newSetFromMap(new IdentityHashMap<>());
        long lights = scene.lights().stream().filter(l -> l.area() == null || areas.add(l.area())).count();
        text.line(lights + " light" + (lights == 1 ? "" : "s") + (lights == scene.lights().size() ? ""
                : " (" + scene.lights().size() + " point lights: each area light is its samples)") + ", at most "
                + WhittedShader.BOUNCES + " bounces; the camera's ray:");
        Rgb colour = new ShadingExplanation(text).shade(scene, ray);
        text.line("pixel colour: each channel clamped to [0, 1], then floor(255·c + ½): "
                + Numbers.rgb(colour.toColor()));
        text.out();
    }

    @Override
    public void ray(Ray ray, Hit hit, int remaining) {
        Frame parent = open.peek();
        Kind kind = parent == null ? Kind.CAMERA : parent.childIsReflection ? Kind.REFLECTED : Kind.REFRACTED;
        segments.add(RayTree.segment(kind, ray, hit, open.size()));
        Frame frame = new Frame();
        open.push(frame);
        text.in().line("ray O = " + Numbers.of(ray.origin()) + ", R = " + Numbers.of(ray.direction()) + ", " + remaining
                + " bounce" + (remaining == 1 ? "" : "s") + " left");
        if (hit == null) {
            text.line("hits nothing: the background (ambient) colour");
            return;
        }
        frame.material = hit.object().material();
        frame.hasBack = !hit.object().isSolid();
        text.line("hits #" + (hit.index() + 1) + " " + hit.object().kind() + " at t = " + Numbers.of(hit.t()) + ", P = "
                + Numbers.of(hit.point()) + ", |P − O| = " + Numbers.of(hit.distance()) + ", colour "
                + (hit.object().isPatterned() ? "from its pattern, at under = P − ε·N" : hit.object().color()));
    }

    @Override
    public void surface(Surface surface) {
        Material m = surface.material();
        String turned = open.peek().hasBack ? " (the ray meets its back: N turned round)"
                : " (the ray is inside: N turned round)";
        if (surface.hit().object() instanceof Triangle triangle && triangle.isSmooth()) {
            float[] w = triangle.cornerWeights(surface.hit().point());
            text.line("smooth: N = normalize(w1·n1 + w2·n2 + w3·n3), the corners' normals n1 = "
                    + Numbers.of(triangle.cornerNormal(0))
                    + ", n2 = " + Numbers.of(triangle.cornerNormal(1)) + ", n3 = "
                    + Numbers.of(triangle.cornerNormal(2)) + " by P's weights (the area across from each corner) w = "
                    + Numbers.of(w[0], w[1], w[2]));
        }
        text.line("N = " + Numbers.of(surface.normal()) + (surface.inside() ? turned : "")
                + ", E = −R/|R| = " + Numbers.of(surface.eye()) + ", over = P + ε·N = " + Numbers.of(surface.over()));
        text.line("finish: ambient " + Numbers.of(m.ambient()) + ", diffuse " + Numbers.of(m.diffuse()) + ", specular "
                + Numbers.of(m.specular()) + ", shininess " + Numbers.of(m.shininess()) + ", reflective "
                + Numbers.of(m.reflective()) + ", transparency " + Numbers.of(m.transparency())
                + ", ior " + Numbers.of(m.ior()));
        lightNumber = 0;
    }

    @Override
    public PatternObserver patterns() {
        return new PatternSteps(text);
    }

    @Override
    public void shadowRay(Light light, Ray ray, Hit hit, float distance) {
        this.shadowRay = ray;
        this.blocker = hit;
        this.lightDistance = distance;
    }

    @Override
    public void light(Light light, boolean shadowed, LightTerms terms) {
        Frame frame = open.peek();
        frame.surface = frame.surface.plus(terms.sum());
        // while explaining, the shader sends a shadow ray towards every light
        segments.add(new Segment(shadowed ? Kind.SHADOW_BLOCKED : Kind.SHADOW_LIT, shadowRay.origin(),
                shadowed ? blocker.point() : light.position(), shadowRay.direction(), open.size() - 1));
        if (light.area() != null) {
            areaSample(light, shadowed, terms);
            return;
        }
        lightNumber++;
        text.line("light " + lightNumber + " at " + Numbers.of(light.position())
                + ", intensity " + Numbers.of(light.intensity())
                + ":").in();
        String verdict = blocker == null ? "hits nothing: lit"
                : "hits #" + (blocker.index() + 1) + " " + blocker.object().kind() + " at |P − O| = "
                        + Numbers.of(blocker.distance()) + (shadowed ? " < " : " ≥ ") + Numbers.of(lightDistance)
                        + " (the light's distance less ε = " + Numbers.of(light.clearance()) + "): "
                        + (shadowed ? "in shadow" : "lit (it lies beyond the light)");
        text.line("shadow ray from over along " + Numbers.of(shadowRay.direction()) + " " + verdict);
        text.line("N·L = " + Numbers.of(terms.lightFacing())
                + (terms.lightFacing() <= 0 ? " ≤ 0: the light is behind the surface" : "")
                + (Float.isNaN(terms.reflectionToEye()) ? "" : ", Rl·E = " + Numbers.of(terms.reflectionToEye())));
        text.line("ambient  = ambient·c⊙I = " + Numbers.of(terms.ambient()));
        text.line("diffuse  = diffuse·c⊙I·(N·L) = " + Numbers.of(terms.diffuse()));
        text.line("specular = specular·I·(Rl·E)^shininess = " + Numbers.of(terms.specular()));
        text.out();
    }

    /** One sample of an area light: the first opens its lines, each of at most 16 has one, the last counts the lit. */
    private void areaSample(Light light, boolean shadowed, LightTerms terms) {
        AreaLight area = light.area();
        if (samplesSeen == 0) {
            lightNumber++;
            areaSum = Rgb.BLACK;
            samplesLit = 0;
            text.line("light " + lightNumber + ", an area light: corner " + Numbers.of(area.corner()) + ", edges u = "
                    + Numbers.of(area.u()) + ", v = " + Numbers.of(area.v()) + ", " + area.n() + " × " + area.m()
                    + " samples, each a point light of intensity I/(n·m) at C + (i + ½)/n·u + (j + ½)/m·v:").in();
        }
        boolean lit = !shadowed && terms.lightFacing() > 0;
        samplesLit += lit ? 1 : 0;
        areaSum = areaSum.plus(terms.sum());
        if (area.sampleCount() <= 16) {
            text.line("sample (" + samplesSeen / area.m() + ", " + samplesSeen % area.m() + ") at "
                    + Numbers.of(light.position()) + ": "
                    + (shadowed ? "in shadow of #" + (blocker.index() + 1) + " " + blocker.object().kind()
                            : terms.lightFacing() > 0 ? "lit" : "behind the surface")
                    + ", N·L = " + Numbers.of(terms.lightFacing()) + ", terms summed " + Numbers.of(terms.sum()));
        }
        samplesSeen++;
        if (samplesSeen == area.sampleCount()) {
            text.line(samplesLit + " of " + area.sampleCount() + " samples lit; the area light gives "
                    + Numbers.of(areaSum));
            text.out();
            samplesSeen = 0;
        }
    }

    @Override
    public void reflected(Ray ray) {
        Frame frame = open.peek();
        frame.reflectionSaid = true;
        frame.childIsReflection = true;
        text.line("reflection along R − 2(R·N)N, from over (× reflective " + Numbers.of(frame.material.reflective())
                + "):");
    }

    @Override
    public void refracted(Ray ray, Snell snell) {
        Frame frame = open.peek();
        sayNoReflection(frame);
        frame.refractionSaid = true;
        frame.childIsReflection = false;
        text.line("refraction (× transparency " + Numbers.of(frame.material.transparency()) + ", ior "
                + Numbers.of(frame.material.ior()) + "):");
        text.in().line(snellNumbers(snell) + ", cos θt = √(1 − sin²θt) = " + Numbers.of(snell.cosTransmitted()));
        text.line("from under = P − ε·N = " + Numbers.of(ray.origin()) + ", along (n·cos θi − cos θt)·N − n·E:").out();
    }

    @Override
    public void totalInternalReflection(Snell snell) {
        Frame frame = open.peek();
        sayNoReflection(frame);
        frame.refractionSaid = true;
        text.line("refraction: none, total internal reflection (black): " + snellNumbers(snell) + " > 1");
    }

    private static String snellNumbers(Snell snell) {
        return "n = n1/n2 = " + Numbers.of(snell.from()) + "/" + Numbers.of(snell.to()) + ", cos θi = E·N = "
                + Numbers.of(snell.cosIncidence()) + ", sin²θt = n²(1 − cos²θi) = "
                + Numbers.of(snell.sin2Transmitted());
    }

    @Override
    public void fresnel(float reflectance) {
        Frame frame = open.peek();
        sayMissing(frame);
        frame.reflectance = reflectance;
        text.line("Fresnel (Schlick): reflectance R = " + Numbers.of(reflectance));
    }

    @Override
    public void colour(Rgb colour) {
        Frame frame = open.pop();
        if (frame.material != null) {
            sayMissing(frame);
        }
        text.line("colour = " + (frame.material != null ? sum(frame) + " = " : "") + Numbers.of(colour)).out();
        Frame parent = open.peek();
        if (parent != null && parent.childIsReflection) {
            parent.reflection = colour;
        } else if (parent != null) {
            parent.refraction = colour;
        }
    }

    /** Step 6's sum as the shader adds it (R and 1 − R where Schlick mixes), first in words, then in numbers. */
    private static String sum(Frame frame) {
        if (frame.reflection == null && frame.refraction == null) {
            return "surface (the lights' terms summed)";
        }
        boolean mixed = !Float.isNaN(frame.reflectance);
        String words = "surface";
        String numbers = Numbers.of(frame.surface);
        if (frame.reflection != null) {
            words += " + reflective·reflection" + (mixed ? "·R" : "");
            numbers += " + " + Numbers.of(frame.material.reflective()) + "·" + Numbers.of(frame.reflection)
                    + (mixed ? "·" + Numbers.of(frame.reflectance) : "");
        }
        if (frame.refraction != null) {
            words += " + transparency·refraction" + (mixed ? "·(1 − R)" : "");
            numbers += " + " + Numbers.of(frame.material.transparency()) + "·" + Numbers.of(frame.refraction)
                    + (mixed ? "·" + Numbers.of(1 - frame.reflectance) : "");
        }
        return words + " = " + numbers;
    }

    private void sayMissing(Frame frame) {
        sayNoReflection(frame);
        if (!frame.refractionSaid) {
            frame.refractionSaid = true;
            text.line("refraction: none (" + (frame.material.transparency() <= 0 ? "transparency 0" : "no bounces left")
                    + ")");
        }
    }

    private void sayNoReflection(Frame frame) {
        if (!frame.reflectionSaid) {
            frame.reflectionSaid = true;
            text.line("reflection: none (" + (frame.material.reflective() <= 0 ? "reflective 0" : "no bounces left")
                    + ")");
        }
    }
}
