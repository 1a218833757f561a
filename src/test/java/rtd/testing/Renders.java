package rtd.testing;

import rtd.accel.Bvh;
import rtd.shade.FlatShader;
import rtd.render.LinearTracer;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.render.RenderResult;
import rtd.scene.Scene;

/** Renders for tests: the parallel renderer in flat colours, with the paper's loop or the BVH. */
public final class Renders {

    private Renders() {
    }

    /** {@code scene} at {@code w × h} on {@code threads} threads, through a BVH or the paper's loop. */
    public static RenderResult parallel(Scene scene, int w, int h, int threads, boolean bvh) {
        FlatShader flat = new FlatShader(scene);
        if (bvh) {
            Bvh hierarchy = Bvh.build(scene);
            return ParallelRenderer.render(scene.camera(), hierarchy::newTracer, tracer -> flat, w, h, threads,
                    new RenderProgress());
        }
        return ParallelRenderer.render(scene.camera(), () -> new LinearTracer(scene), tracer -> flat, w, h, threads,
                new RenderProgress());
    }

    /** The pixels of {@link Scene#render}, the paper's own loop, as {@code 0xRRGGBB} row by row. */
    public static int[] paper(Scene scene, int w, int h) {
        int[] rgb = scene.render(w, h).getRGB(0, 0, w, h, null, 0, w);
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF;
        }
        return rgb;
    }
}
