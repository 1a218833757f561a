package rtd.cli;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.function.Function;
import java.util.function.Supplier;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import rtd.accel.Bvh;
import rtd.io.SceneException;
import rtd.io.SceneIO;
import rtd.image.Picture;
import rtd.render.Shader;
import rtd.shade.FlatShader;
import rtd.shade.WhittedShader;
import rtd.render.LinearTracer;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.render.RenderResult;
import rtd.render.Tracer;
import rtd.render.WorkCount;
import rtd.scene.Scene;

/**
 * The command line: {@code java -jar rtd.jar SCENE [-o OUT.png] [--width N] [--height N]}.
 * It reads the scene, renders it and writes the PNG, timing each phase for {@code --stats}.
 */
@Command(name = "rtd", mixinStandardHelpOptions = true, versionProvider = VersionProvider.class,
        sortOptions = false, usageHelpAutoWidth = true,
        description = "Renders a scene file to a PNG by ray tracing, as the \"3D Raytracing Demo Project\" does.",
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {
            "0:the picture was written",
            "1:the scene file has mistakes, a file could not be read or written, or rendering failed",
            "2:the command line is wrong"},
        footer = {"%nExample:%n  java -jar rtd.jar examples/input_rtd.txt -o out.png",
            "The scene format and every error message: see README.md and docs/errors.md."})
public final class RtdCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE", converter = FileName.class, description = "the scene file to render")
    private Path scenePath;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT.png", converter = FileName.class,
            description = "where to write the picture (default: SCENE with .png in place of its extension)")
    private Path output;

    @Option(names = "--width", paramLabel = "N", defaultValue = "1920", converter = PositiveInt.class,
            description = "image width in pixels (default: ${DEFAULT-VALUE})")
    private int width;

    @Option(names = "--height", paramLabel = "N", defaultValue = "1080", converter = PositiveInt.class,
            description = "image height in pixels (default: ${DEFAULT-VALUE})")
    private int height;

    @Option(names = "--threads", paramLabel = "N", converter = ThreadCount.class,
            description = "threads to render, build the BVH and compress the PNG with (default: all cores, here "
                    + "${DEFAULT-VALUE}; a larger N uses at most 4 threads per core)")
    private int threads = Runtime.getRuntime().availableProcessors();

    @Option(names = "--accel", paramLabel = "KIND", defaultValue = "auto",
            description = "none: the paper's loop over every object; bvh: a bounding volume hierarchy; "
                    + "auto: bvh for any scene with objects (default: ${DEFAULT-VALUE})")
    private Accel accel;

    @Option(names = "--paper", description = "render with the paper's own code, Scene.render (Listing 4.2) and its loop "
            + "over every object (Listing 4.3), on one thread; --accel and --threads do not apply")
    private boolean paper;

    @Option(names = "--samples", paramLabel = "N", defaultValue = "1", converter = PositiveInt.class,
            description = "anti-aliasing: N x N rays per pixel, their colours averaged (default: ${DEFAULT-VALUE}, "
                    + "one ray through the pixel's corner, as the paper)")
    private int samples;

    @Option(names = "--stats", description = "print the time of each phase and the work per ray to standard error")
    private boolean stats;

    @Option(names = "--no-progress", description = "never show the progress line (it shows only on a terminal)")
    private boolean noProgress;

    @Option(names = "--debug", description = "show the stack trace of an error")
    private boolean debug;

    /** Issue 11: --explain, --view, --export-pov and --watch, all in {@link TeachingOptions}. */
    @Mixin
    private TeachingOptions teaching;

    /** The command line of rtd, with its error handlers, ready to {@code execute}. */
    public static CommandLine commandLine() {
        CommandLine commandLine = new CommandLine(new RtdCommand());
        commandLine.setParameterExceptionHandler(new UsageErrorHandler());
        commandLine.setExecutionExceptionHandler((ex, cmd, parseResult) -> {
            PrintWriter err = cmd.getErr();
            err.println("rtd: internal error: " + ex + ". This is a bug in rtd; please report it with the scene.");
            if (((RtdCommand) cmd.getCommand()).debug) {
                ex.printStackTrace(err);
            }
            err.flush();
            return 1;
        });
        return commandLine;
    }

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        try {
            Integer taught = teaching.run(err); // issue 11: null unless a teaching option answers instead of the render
            return taught != null ? taught : render(err);
        } catch (SceneException e) {
            err.print(e.report());
            printDebug(err, e);
            return 1;
        } catch (FileError e) {
            err.println("rtd: " + e.getMessage());
            printDebug(err, e);
            return 1;
        } catch (OutOfMemoryError e) {
            err.println(Memory.outOfMemory(Runtime.getRuntime().maxMemory(), Memory.physical()));
            return 1;
        } finally {
            err.flush();
        }
    }

    private int render(PrintWriter err) throws SceneException, FileError {
        OutputTarget target = outputTarget();
        PhaseTimer timer = new PhaseTimer();
        Scene scene = readScene();
        timer.endPhase("parse");
        ImageSize.check(spec.commandLine(), width, height);

        Bvh bvh = paper ? null : buildBvh(scene);
        timer.endPhase("build");

        RenderResult result = paper ? renderAsThePaper(scene, err) : renderInParallel(scene, bvh, err);
        timer.endPhase("render");

        writePicture(result, target, threads);
        timer.endPhase("write");
        if (stats) {
            err.print(StatsReport.format(timer, scene, bvh, result.work(), threads, target.spelt()));
        }
        return 0;
    }

    /** The BVH, if {@code --accel} asks for one: {@code auto} takes it for any scene with objects. */
    private Bvh buildBvh(Scene scene) {
        boolean useBvh = accel == Accel.bvh || accel == Accel.auto && !scene.objects().isEmpty();
        return useBvh ? Bvh.build(scene, threads) : null;
    }

    /**
     * All cores, with the BVH's tracer or the paper's loop ({@link LinearTracer}); in flat
     * colours, or shaded ({@link WhittedShader}) if the scene has lights.
     */
    private RenderResult renderInParallel(Scene scene, Bvh bvh, PrintWriter err) {
        Supplier<Tracer> tracers = bvh != null ? bvh::newTracer : () -> new LinearTracer(scene);
        FlatShader flat = new FlatShader(scene);
        Function<Tracer, Shader> shaders = scene.lights().isEmpty() ? tracer -> flat : tracer -> new WhittedShader(scene, tracer);
        RenderProgress progress = new RenderProgress();
        boolean showProgress = !noProgress && Terminal.stderrIsTerminal();
        try (ProgressDisplay display = ProgressDisplay.start(showProgress, err, progress, width, height)) {
            return ParallelRenderer.render(scene.camera(), tracers, shaders, width, height, samples, threads, progress);
        }
    }

    /**
     * {@code --paper}: the paper's {@link Scene#render} itself, one ray per pixel on this
     * thread, in the paper's flat colours.
     */
    private RenderResult renderAsThePaper(Scene scene, PrintWriter err) {
        if (!scene.lights().isEmpty() || samples > 1) {
            err.println("rtd: note: --paper draws as the paper does, one ray per pixel in flat colours: "
                    + "the scene's lights and --samples are not used");
        }
        BufferedImage image = scene.render(width, height);
        int[] rgb = image.getRGB(0, 0, width, height, null, 0, width);
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF; // getRGB adds an opaque alpha channel
        }
        return new RenderResult(new Picture(width, height, rgb), WorkCount.testsOf(scene.objects(), (long) width * height));
    }

    private Scene readScene() throws SceneException, FileError {
        try {
            return SceneIO.readScene(scenePath);
        } catch (IOException e) {
            throw new FileError("cannot read the scene file '" + scenePath + "': " + FileProblems.reason(e), e);
        }
    }

    private static void writePicture(RenderResult result, OutputTarget target, int threads) throws FileError {
        try {
            if (target.kind() == OutputTarget.Kind.STREAM) {
                SceneIO.writePngInto(result.image(), target.file(), threads);
            } else {
                SceneIO.writePng(result.image(), target.file(), threads);
            }
        } catch (IOException e) {
            throw new FileError("cannot write '" + target.spelt() + "': " + FileProblems.reason(e), e);
        }
    }

    /**
     * Where the picture goes: {@code -o}, or the scene's name with {@code .png}; checked before
     * rendering, on the real files behind any symbolic link, so that a long render does not end
     * in a failed write and nothing but a regular file is ever replaced.
     */
    private OutputTarget outputTarget() throws FileError {
        if (Files.isDirectory(scenePath)) {
            // before the default output, which a folder such as / has no name for
            throw new FileError("cannot read the scene file '" + scenePath + "': it is a folder, not a file", null);
        }
        Path spelt = output != null ? output : defaultOutput(scenePath);
        OutputTarget target;
        try {
            target = OutputTarget.of(spelt, scenePath);
        } catch (OutputTarget.Refusal refusal) {
            if (refusal.misuse()) {
                throw new ParameterException(spec.commandLine(), refusal.getMessage());
            }
            throw new FileError(refusal.getMessage(), null);
        }
        if (target.folder().isPresent()) {
            checkFolder(spelt, target.folder().get());
        }
        return target;
    }

    private static void checkFolder(Path spelt, Path folder) throws FileError {
        if (!Files.isDirectory(folder)) {
            throw new FileError("cannot write '" + spelt + "': the folder '" + folder + "' "
                    + (Files.exists(folder) ? "is a file, not a folder" : "does not exist"), null);
        }
        if (!Files.isWritable(folder)) {
            throw new FileError("cannot write '" + spelt + "': the folder '" + folder + "' is not writable", null);
        }
    }

    /** {@code scenes/a.txt} gives {@code scenes/a.png}; a name without extension gets {@code .png}. */
    static Path defaultOutput(Path scene) {
        String name = scene.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String base = dot > 0 ? name.substring(0, dot) : name;
        return scene.resolveSibling(base + ".png");
    }

    /** A file that cannot be read or written; the message says which and why. */
    private static final class FileError extends Exception {
        private static final long serialVersionUID = 1L;

        FileError(String message, IOException cause) {
            super(message, cause);
        }
    }

    private void printDebug(PrintWriter err, Exception e) {
        if (debug) {
            e.printStackTrace(err);
        }
    }
}
