package rtd.cli;

import java.io.PrintWriter;
import java.io.Writer;
import java.io.IOException;
import java.util.function.Supplier;
import picocli.CommandLine;
import rtd.accel.Accelerator;
import rtd.accel.Accelerator.StructureCache;
import rtd.io.SceneException;
import rtd.io.SceneFile;
import rtd.render.Tracer;
import rtd.scene.Scene;
import rtd.window.Window;
import rtd.window.WindowSetup;
import rtd.window.WindowSetup.ClockedScene;
import rtd.window.WindowSetup.Engine;
import rtd.window.WindowSetup.FileWatch;

/**
 * {@code --window}: opens the scene in a window ({@link Window}) instead of writing its picture, with the size,
 * samples, threads and tracers the command line gives. Its classes load only when the window is asked for.
 */
public final class WindowRun {

    /** The options that have no meaning in a window, each with what the window does instead. */
    private static final String[][] REFUSED = {{"--explain", "a click on a pixel explains it"},
        {"--view", "keys 2 to 5 show the views"}, {"--watch", "the window renders again whenever the scene is saved"},
        {"--export-pov", "export without --window"}, {"--paper", "--accel none traces with the paper's loop"},
        {"--frames", "render the frames without --window"}, {"-o", "Ctrl+S saves the picture beside the scene"}};

    private WindowRun() {
    }

    /** Opens the window, once what makes no sense in one is refused; the exit code when it is closed. */
    static int run(RenderOptions options, CommandLine commandLine, PrintWriter err) throws SceneException, FileError {
        Misuse.refuse(options.scenes().size() > 1, "--window opens one scene file, but "
                + options.scenes().size() + " were given; open each in a window of its own");
        Misuse.refuse(options.scene().toString().equals("-"), "--window needs a scene file to watch; "
                + "it cannot open standard input ('-')");
        for (String[] refused : REFUSED) {
            Misuse.refuse(commandLine.getParseResult().hasMatchedOption(refused[0]), "--window and "
                    + refused[0] + " do not go together: " + refused[1]);
        }
        String missing = Window.missingDisplay();
        if (missing != null) {
            return noDisplay(err, missing);
        }
        Memory.checkImageFits(options.width(), options.height(), options.scale());
        WindowSetup setup = new WindowSetup(options.scene(), () -> read(options), watch(options),
                engine(options.accel(), options.threads()), options.width(), options.height(), options.samples(),
                options.threads(), options.clock());
        try {
            Window.open(setup);
            return 0;
        } catch (Window.NoDisplay e) {
            return noDisplay(err, e.getMessage());
        } catch (IOException e) {
            throw e.getCause() instanceof FileError error ? error : new FileError(e.getMessage());
        }
    }

    /** No screen to open the window on (a server, SSH without X, CI): exit code 2, as for a misuse. */
    private static int noDisplay(PrintWriter err, String why) {
        err.println("rtd: --window needs a desktop, and there is none here (" + why + "); -o writes the picture to a "
                + "file instead, such as -o picture.png");
        return 2;
    }

    /** The scene file, read once, each scene parsed from it at {@code --scale} (its warnings not shown). */
    private static ClockedScene read(RenderOptions options) throws IOException {
        try {
            SceneFile file = SceneSource.of(options.scene()).readFile(null, options.parseThreads());
            return new ClockedScene(file, options.scale()::of);
        } catch (FileError e) {
            throw new IOException(e.getMessage(), e);
        }
    }

    /**
     * The tracers {@code --accel} chooses, chained as for {@code -o}: for any camera the lights' grids (they see from
     * the lights) before the BVH, or the paper's loop; for the picture its view grid before those. Public for tests.
     */
    public static Engine engine(Accelerator.Choice accel, int threads) {
        StructureCache kept = new StructureCache(); // a clock that moves only the camera keeps the BVH
        return new Engine() {
            @Override
            public Supplier<Tracer> forPicture(Scene scene, int width, int height, int samples,
                    Supplier<Tracer> anyCamera) {
                return Accelerator.forPicture(accel, scene, width, height, samples, threads, anyCamera);
            }

            @Override
            public Supplier<Tracer> forAnyCamera(Scene scene, int width, int height) {
                return Accelerator.forAnyCamera(accel, scene, width, height, threads, kept);
            }
        };
    }

    /** {@link SceneWatcher} on the scene and its meshes, telling the window of each save (not of the first look). */
    static FileWatch watch(RenderOptions options) {
        return changed -> {
            boolean[] first = {true};
            SceneWatcher watcher = new SceneWatcher(options.scene(), () -> {
                if (!first[0]) {
                    changed.run();
                }
                first[0] = false;
                return 0;
            }, new PrintWriter(Writer.nullWriter()), SceneWatcher.POLL_MILLIS);
            Thread thread = new Thread(watcher::run, "rtd-window-watch");
            thread.setDaemon(true);
            thread.start();
            return watcher::stop;
        };
    }
}
