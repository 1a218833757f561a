package rtd.window;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import rtd.accel.Accelerator;
import rtd.accel.ViewGrid;
import rtd.camera.OrthographicCamera;
import rtd.cli.WindowRun;
import rtd.image.Picture;
import rtd.io.SceneIO;
import rtd.math.Vector3f;
import rtd.scene.Scene;
import rtd.window.WindowSetup.Engine;

/**
 * The window's speed, warm, without a screen: frames rendered as the window renders them ({@link FrameRenderer})
 * and painted into its image (a {@link BufferedImage}, as {@link PicturePanel} does), while the camera orbits
 * ({@link CameraController}); then the time from the mouse resting to the full picture. The paper's example is
 * the window's default view of it (960 × 540 at half its zoom, as {@code --window} opens it).
 *
 * <pre>
 * mvn -q -f bench/pom.xml package && java -cp bench/target/benchmarks.jar rtd.window.WindowFrames [SECONDS]
 * </pre>
 */
public final class WindowFrames {

    private static final int WIDTH = 960;
    private static final int HEIGHT = 540;

    private WindowFrames() {
    }

    public static void main(String[] args) throws Exception {
        double seconds = args.length > 0 ? Double.parseDouble(args[0]) : 5;
        int threads = Runtime.getRuntime().availableProcessors();
        Engine engine = WindowRun.engine(Accelerator.Choice.auto, threads);
        System.out.printf(Locale.ROOT, "%d × %d, %d threads, %.0f s of frames per figure, after as long warming%n",
                WIDTH, HEIGHT, threads, seconds);
        for (String name : new String[] {"input_rtd", "glass_and_mirror"}) {
            Scene scene = SceneIO.readScene(Path.of("examples", name + ".txt"));
            if (name.equals("input_rtd")) {
                scene = halfZoom(scene);
            }
            measure(name, scene, engine, threads, seconds);
        }
    }

    private static void measure(String name, Scene file, Engine engine, int threads, double seconds) {
        WindowSetup setup = new WindowSetup(null, null, null, engine, WIDTH, HEIGHT, 1, threads, 0);
        FrameRenderer renderer = new FrameRenderer(setup, Runnable::run, (pass, newest) -> { }, e -> { });
        CameraController camera = new CameraController(file.camera());
        BufferedImage screen = new BufferedImage(WIDTH, HEIGHT, BufferedImage.TYPE_INT_RGB);
        Vector3f pivot = CameraController.pivot(file, WIDTH, HEIGHT);
        frames(renderer, camera, file, pivot, screen, seconds, FrameRenderer.MOVING); // warming
        double fps = frames(renderer, camera, file, pivot, screen, seconds, FrameRenderer.MOVING);
        double fps4 = frames(renderer, camera, file, pivot, screen, seconds, List.of(4));
        List<Double> full = new ArrayList<>();
        List<Double> grids = new ArrayList<>();
        for (int i = 0; i < 9; i++) {
            camera.orbit(0.05, 0, pivot);
            Scene moved = new Scene(file.ambient(), camera.camera(), file.objects(), file.lights());
            long start = System.nanoTime();
            renderer.render(file, camera.camera(), null, FrameRenderer.RESTED, pass -> paint(pass.picture(), screen));
            full.add((System.nanoTime() - start) / 1e9);
            start = System.nanoTime();
            ViewGrid.build(moved, WIDTH, HEIGHT, 1, threads);
            grids.add((System.nanoTime() - start) / 1e9);
        }
        System.out.printf(Locale.ROOT, "%-17s moving: %.1f frames/s in blocks of 2 × 2 (%d × %d rays), %.1f in "
                + "blocks of 4 × 4; full %d × %d after the mouse rests: %.3f s (median of 9; the view grid's build "
                + "in it %.4f s)%n", name, fps, WIDTH / 2, HEIGHT / 2, fps4, WIDTH, HEIGHT, median(full),
                median(grids));
    }

    /** Frames per second while the camera orbits a little each frame, for {@code seconds}. */
    private static double frames(FrameRenderer renderer, CameraController camera, Scene file, Vector3f pivot,
            BufferedImage screen, double seconds, List<Integer> moving) {
        long start = System.nanoTime();
        long end = start + (long) (seconds * 1e9);
        int frames = 0;
        while (System.nanoTime() < end) {
            camera.orbit(0.02, 0.002 * Math.sin(frames / 10.0), pivot);
            renderer.render(file, camera.camera(), null, moving, pass -> paint(pass.picture(), screen));
            frames++;
        }
        return frames / ((System.nanoTime() - start) / 1e9);
    }

    /** Into the window's image, as {@link PicturePanel#picture} does. */
    private static void paint(Picture picture, BufferedImage screen) {
        screen.setRGB(0, 0, picture.width(), picture.height(), picture.rgb(), 0, picture.width());
    }

    /** The paper's scene as {@code --window} opens it: half the default picture, at half its zoom. */
    private static Scene halfZoom(Scene scene) {
        OrthographicCamera camera = (OrthographicCamera) scene.camera();
        return new Scene(scene.ambient(), new OrthographicCamera(camera.position(), camera.direction(),
                camera.zoom() / 2), scene.objects(), scene.lights());
    }

    private static double median(List<Double> values) {
        List<Double> sorted = new ArrayList<>(values);
        Collections.sort(sorted);
        return sorted.get(sorted.size() / 2);
    }
}
