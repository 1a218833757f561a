package rtd.accel;

import java.util.Map;
import java.util.TreeMap;
import rtd.camera.ICamera;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.math.Ray;
import rtd.render.HitBuffer;
import rtd.render.LinearTracer;
import rtd.render.RayBundle;
import rtd.render.Tracer;
import rtd.render.WorkCount;

/**
 * Answers the camera's rays from a {@link HitImage}: each ray's hit was found before the render,
 * so a ray reads it from its pixel. A bundle whose pixels all show nothing, or (for a shader
 * that reads only the objects: flat colours) all one object, is answered at once.
 *
 * <p>A ray that is not one of the image's (a ray given alone, a ray through another point of its
 * pixel) goes to the tracer for the others if there is one, else runs the tests on every object,
 * as the paper's loop does: right for any ray, and fast only for the camera's.
 *
 * <p>Not thread-safe: it keeps counters of its own. Use one per thread.
 */
public final class HitImageTracer implements Tracer {

    private final HitImage image;
    /** The tracer of the rays that are not the image's: the one given, else the paper's loop, made when first needed. */
    private Tracer others;
    private long rays;
    /** Per kind of the objects with a box, the tests of the rays answered from the image. */
    private final long[] tests;

    HitImageTracer(HitImage image, Tracer others) {
        this.image = image;
        this.others = others;
        this.tests = new long[image.testsOfKind.length];
    }

    /** The tracer for the others' rays, else the paper's loop over every object, for any ray. */
    @Override
    public Hit nearestHit(Ray ray) {
        return others().nearestHit(ray);
    }

    /** The tracer for the rays that are not the image's. */
    private Tracer others() {
        if (others == null) {
            others = new LinearTracer(image.scene);
        }
        return others;
    }

    /** A shadow ray's question, for the tracer for the others' rays, else from the loop's hit. */
    @Override
    public boolean blocked(Ray ray, float distance) {
        return others().blocked(ray, distance);
    }

    /** The camera's rays read their pixels; other rays go to the tracer for them, or one by one to the loop. */
    @Override
    public void traceAll(RayBundle bundle, HitBuffer hits) {
        if (!serves(bundle)) {
            others().traceAll(bundle, hits);
            return;
        }
        int squareWidth = bundle.right() - bundle.left();
        for (int i = 0; i < bundle.count(); i++) {
            int pixel = pixel(bundle, i, squareWidth);
            hits.set(i, image.index[pixel], image.t[pixel], image.distance[pixel]);
            hits.setTests(i, count(pixel));
        }
        rays += bundle.count();
    }

    /**
     * The camera's rays of pixels that all show nothing, or all one object where only the object
     * is read ({@link HitBuffer#hitPointsRead}), at once. Unlike a beam's answer, each ray took
     * tests (those of the objects whose footprint holds its pixel, run in the build), and they are
     * written to {@code hits} one by one for {@code --view cost}.
     */
    @Override
    public boolean traceAtOnce(RayBundle bundle, HitBuffer hits) {
        if (!serves(bundle)) {
            return others != null && others.traceAtOnce(bundle, hits);
        }
        int squareWidth = bundle.right() - bundle.left();
        int first = image.index[pixel(bundle, 0, squareWidth)];
        if (first >= 0 && hits.hitPointsRead()) {
            return false;
        }
        for (int y = bundle.top(); y < bundle.bottom(); y++) {
            for (int x = bundle.left(); x < bundle.right(); x++) {
                if (image.index[y * image.width + x] != first) {
                    return false;
                }
            }
        }
        rays += bundle.count();
        if (first < 0) {
            hits.setMisses(bundle.count());
        } else {
            hits.setHits(first, bundle.count());
        }
        for (int i = 0; i < bundle.count(); i++) { // the tests were run, in the build: each ray has its own
            hits.setTests(i, count(pixel(bundle, i, squareWidth)));
        }
        return true;
    }

    /**
     * Every camera ray of the image's own picture at once: the objects its pixels show, read
     * as they are, and each ray's tests counted as when rays read their pixels bundle by bundle.
     */
    @Override
    public int[] traceEveryPixel(ICamera camera, int width, int height) {
        if (camera != image.camera || width != image.width || height != image.height) {
            return null;
        }
        for (int k = 0; k < tests.length; k++) {
            long sum = 0;
            for (int ofPixel : image.testsOfKind[k]) {
                sum += ofPixel;
            }
            tests[k] += sum;
        }
        rays += (long) width * height;
        return image.index;
    }

    /** The pixel of ray {@code i} of a bundle the image serves. */
    private int pixel(RayBundle bundle, int i, int squareWidth) {
        return (bundle.top() + i / squareWidth) * image.width + bundle.left() + i % squareWidth;
    }

    /** Adds the tests of the ray of {@code pixel} to this tracer's, and answers how many they were. */
    private int count(int pixel) {
        int all = image.unbounded.length;
        for (int k = 0; k < tests.length; k++) {
            int ofKind = image.testsOfKind[k][pixel];
            tests[k] += ofKind;
            all += ofKind;
        }
        return all;
    }

    /** Whether the bundle holds rays of the image's camera and picture, through the corners of pixels of the picture. */
    private boolean serves(RayBundle bundle) {
        return bundle.camera() == image.camera && bundle.width() == image.width && bundle.height() == image.height
                && bundle.left() >= 0 && bundle.top() >= 0 && bundle.right() <= image.width
                && bundle.bottom() <= image.height && bundle.sampleX() == 0 && bundle.sampleY() == 0;
    }

    @Override
    public long testsRun() {
        long all = rays * image.unbounded.length;
        for (long ofKind : tests) {
            all += ofKind;
        }
        return all + (others != null ? others.testsRun() : 0);
    }

    @Override
    public WorkCount work() {
        Map<String, Long> byKind = new TreeMap<>();
        for (int k = 0; k < tests.length; k++) {
            byKind.merge(image.kindNames[k], tests[k], Long::sum);
        }
        for (IGeometry object : image.unbounded) {
            byKind.merge(object.kind(), rays, Long::sum);
        }
        WorkCount own = new WorkCount(rays, byKind, 0).answeredBy("image of hits");
        return others != null ? own.plus(others.work()) : own;
    }
}
