package rtd.cli;

import java.io.File;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.IVersionProvider;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import rtd.accel.Accelerator;
import rtd.io.ImageFormat;
import rtd.io.SceneException;
import rtd.view.View;

/**
 * The command line: {@code java -jar rtd.jar SCENE... [-o OUT] [options]}. It checks the whole command line first,
 * where each picture goes included: a mistake there (exit code 2) stops everything before any work. Then it renders
 * each scene ({@link SceneRun}); one that fails (exit code 1) does not keep the others from being rendered.
 */
@Command(name = RtdCommand.NAME, mixinStandardHelpOptions = true, versionProvider = RtdCommand.Version.class,
        sortOptions = false, usageHelpAutoWidth = true,
        description = {"Renders scene files to pictures by ray tracing, as the \"3D Raytracing Demo Project\" does.",
            "Each SCENE is written beside it, as SCENE with .png in place of its extension, unless -o names the "
                + "picture. SCENE '-' reads the scene from standard input (it needs -o)."},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {
            "0:every picture was written (perhaps with warnings: nothing in view, a slip in the scene)",
            "1:a scene file has mistakes, a file could not be read or written, or rendering failed",
            "2:the command line is wrong"},
        footer = {"%nExamples:",
            "  java -jar rtd.jar examples/input_rtd.txt -o out.png",
            "  java -jar rtd.jar examples/input_rtd.txt --scale 0.25 -o thumbnail.jpg",
            "  java -jar rtd.jar examples/*.txt",
            "  java -jar rtd.jar examples/orbit.txt --frames 60 -o orbit.gif",
            "The scene format and every message: see README.md and docs/errors.md."})
public final class RtdCommand implements Callable<Integer> {

    static final String NAME = "java -jar rtd.jar";
    /** The paper's picture size. */
    static final int DEFAULT_WIDTH = 1920;
    static final int DEFAULT_HEIGHT = 1080;

    @Spec
    private CommandSpec spec;

    private final StandardStreams streams;

    @Parameters(index = "0..*", arity = "1..*", paramLabel = "SCENE", converter = OptionValues.FileName.class,
            description = "the scene files to render; '-' is standard input")
    private List<Path> scenePaths;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT", converter = OptionValues.OutputFile.class,
            description = "where to write the picture, with one SCENE: its extension chooses the format (.png, .jpg, "
                    + ".bmp, ...; PNG if it has none); '-' is standard output, as PNG "
                    + "(default: SCENE with .png in place of its extension)")
    private Path output;

    @Option(names = "--width", paramLabel = "N", defaultValue = "" + DEFAULT_WIDTH,
            converter = OptionValues.PositiveWhole.class,
            description = "image width in pixels (default: ${DEFAULT-VALUE})")
    private int width;

    @Option(names = "--height", paramLabel = "N", defaultValue = "" + DEFAULT_HEIGHT,
            converter = OptionValues.PositiveWhole.class,
            description = "image height in pixels (default: ${DEFAULT-VALUE})")
    private int height;

    @Option(names = "--scale", paramLabel = "F", defaultValue = "1", converter = OptionValues.ScaleFactor.class,
            description = "the same view at another size: multiplies the width and height (given or default) and "
                    + "the orthographic camera's zoom by F, so that --scale 0.25 renders 480x270 pixels of what "
                    + "1920x1080 shows (default: ${DEFAULT-VALUE})")
    private Scale scale;

    @Option(names = "--threads", paramLabel = "N", converter = OptionValues.Threads.class,
            description = "threads to render and build with (default: all cores, here "
                    + "${DEFAULT-VALUE}; a larger N uses at most 4 threads per core)")
    private int threads = Runtime.getRuntime().availableProcessors();

    @Option(names = "--accel", paramLabel = "KIND", defaultValue = "auto",
            description = "none: the paper's loop over every object; bvh: a bounding volume hierarchy; "
                    + "grid: a grid on the image for the camera's rays (with lights: a grid seen from each light for "
                    + "its shadow rays, and bvh for the rest); auto: grid (default: ${DEFAULT-VALUE})")
    private Accelerator.Choice accel;

    @Option(names = "--paper", description = "render with the paper's own code, Scene.render (Listing 4.2) and its "
            + "loop over every object (Listing 4.3), on one thread; --accel and --threads do not apply")
    private boolean paper;

    @Option(names = "--samples", paramLabel = "N", defaultValue = "1", converter = OptionValues.Samples.class,
            description = "anti-aliasing: N x N rays per pixel, N from 1 to 16, their colours averaged (default: "
                    + "${DEFAULT-VALUE}, one ray through the pixel's corner, as the paper)")
    private int samples;

    @Option(names = "--stats", description = "print the time of each phase and the work per ray to standard error")
    private boolean stats;

    @Option(names = "--no-progress", description = "never show the progress line (it shows only on a terminal)")
    private boolean noProgress;

    @Option(names = "--debug", description = "show the stack trace of an error")
    private boolean debug;

    @Option(names = "--explain", paramLabel = "X,Y", description = "instead of a picture, print what rtd does for "
            + "pixel (X, Y), step by step in the paper's terms: the ray, each object's intersection test, the depth "
            + "test and the colour (with lights: each light's terms and the reflected and refracted rays)")
    private String explain;

    @Option(names = "--view", paramLabel = "KIND", description = "instead of the picture, draw what the rays did: "
            + "cost (intersection tests per ray, a heat map with its scale), depth (|P - O| in grey, near bright), "
            + "normal (the normal as colour), id (a colour per object); default output SCENE-KIND.png")
    private View view;

    @Option(names = "--export-pov", paramLabel = "FILE.pov", converter = OptionValues.OutputFile.class,
            description = "also write the scene as a POV-Ray 3.7 scene that draws the same picture; its first lines "
                    + "give the povray command")
    private Path exportPov;

    @Option(names = "--watch", description = "after the first render, render again whenever the scene file (or a mesh "
            + "it uses) changes, until Ctrl-C; a broken edit prints its errors and keeps the last good picture")
    private boolean watch;

    @Option(names = "--window", description = "instead of writing the picture, open the scene in a window (960x540 "
            + "unless --width, --height or --scale say otherwise): it renders coarse at once and refines; drag to "
            + "orbit, right-drag to pan, wheel to zoom, click a pixel to see its rays and --explain; keys 1-5 picture "
            + "and views, R reset, C copy the camera line, P play the clock, Ctrl+S save, Q quit; saving the scene "
            + "renders it again; --clock C is the clock it starts at")
    private boolean window;

    @Option(names = "--clock", paramLabel = "C", converter = OptionValues.FiniteNumber.class,
            description = "the value of clock in the scene's expressions (default: 0)")
    private Double clock;

    @Option(names = "--frames", paramLabel = "N", converter = OptionValues.FrameCount.class,
            description = "draw N pictures (N at least 2), frame i at clock = i/(N-1): -o NAME.png writes "
                    + "NAME-000.png, NAME-001.png, ...; -o NAME.gif one looping animated GIF")
    private Integer frames;

    @Option(names = "--fps", paramLabel = "F", converter = OptionValues.FramesPerSecond.class,
            description = "frames per second of the animated GIF (default: 24)")
    private Double fps;

    @Option(names = "--subset", paramLabel = "A-B", description = "with --frames: draw only frames A to B (from 0, "
            + "inclusive), with the clocks and names they have in the whole animation")
    private String subset;

    private RtdCommand(StandardStreams streams) {
        this.streams = streams;
    }

    public static void main(String[] args) {
        WarmUp.start(ImageFormat.PNG); // the usual format, warmed while picocli starts and the scene is read
        System.exit(commandLine().execute(args));
    }

    /** The command line of rtd, writing in the terminal's encoding, ready to {@code execute}. */
    public static CommandLine commandLine() {
        CommandLine commandLine = commandLine(StandardStreams.system());
        commandLine.setOut(StandardStreams.printWriter(System.out, StandardStreams.encodingOf("stdout")));
        commandLine.setErr(StandardStreams.printWriter(System.err, StandardStreams.encodingOf("stderr")));
        return commandLine;
    }

    /** The command line with {@code streams} for {@code -} and {@code -o -}; a misuse gets one line and a hint. */
    static CommandLine commandLine(StandardStreams streams) {
        CommandLine commandLine = new CommandLine(new RtdCommand(streams));
        commandLine.setParameterExceptionHandler((ex, args) -> Misuse.report(ex));
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

    /** {@code --version}: the version in the jar's manifest. */
    static final class Version implements IVersionProvider {
        @Override
        public String[] getVersion() {
            String version = RtdCommand.class.getPackage().getImplementationVersion();
            return new String[] {"rtd " + (version != null ? version : "(development build, not from the jar)"),
                "Java " + System.getProperty("java.version")};
        }
    }

    @Override
    public Integer call() {
        CommandLine commandLine = spec.commandLine();
        PrintWriter err = commandLine.getErr();
        try {
            TeachingRun teaching = new TeachingRun(explain, view, exportPov, watch);
            FramePlan frames = FramePlan.of(this.frames, subset, fps, clock != null, scenePaths, output,
                    window ? "--window" : teaching.replacingOption());
            if (window) {
                return WindowRun.run(options(true), commandLine, err);
            }
            Integer taught = teaching.run(options(false), commandLine, err); // null: no teaching option answers
            if (taught != null) {
                return taught;
            }
            List<JobPlanner.Job> jobs = new JobPlanner(output, streams).jobs(scenePaths);
            RenderOptions options = options(true);
            Memory.checkImageFits(options.width(), options.height(), scale); // before any write
            OutputTarget export = teaching.planExport(options); // beside the picture: one scene
            if (paper && (given("--accel") || given("--threads"))) { // once every misuse has had its say
                err.println("rtd: note: --paper renders with the paper's loop on one thread; --accel and --threads are "
                        + "not used");
            }
            if (output != null && output.toString().indexOf('\\') >= 0 && File.separatorChar == '/') {
                err.println("rtd: note: '" + output + "' has backslashes, which this system keeps in the file's name; "
                        + "it separates folders with '/'");
            }
            CompletableFuture<Void> writerReady = WarmUp.start(jobs.get(0).format());
            return jobs.stream().mapToInt(job -> run(job, options, writerReady, export, frames, err)).max().orElse(0);
        } catch (SceneException | FileError e) {
            return failed(err, e);
        } catch (Misuse e) {
            throw new ParameterException(commandLine, e.getMessage());
        } finally {
            err.flush();
        }
    }

    /** One scene's run, with {@code export} (or null) written once the scene is read; its exit code. */
    private int run(JobPlanner.Job job, RenderOptions options, CompletableFuture<Void> writerReady, OutputTarget export,
            FramePlan frames, PrintWriter err) {
        try {
            if (job.refusal() != null) {
                throw job.refusal();
            }
            if (job.source().stdin() && streams.inIsTerminal()) {
                err.println("rtd: reading the scene from standard input; end it with Ctrl-D");
                err.flush();
            }
            new SceneRun(options, streams, err, frames).run(job, writerReady, export);
            return 0;
        } catch (SceneException | FileError e) {
            return failed(err, e);
        } catch (OutOfMemoryError e) {
            err.println(Memory.outOfMemory(Runtime.getRuntime().maxMemory(), Memory.physical()));
            return 1;
        } finally {
            err.flush();
        }
    }

    private int failed(PrintWriter err, Exception e) {
        err.print(e instanceof SceneException scene ? scene.report() : "rtd: " + e.getMessage() + "\n");
        if (debug) {
            e.printStackTrace(err);
        }
        return 1;
    }

    /** The options, sizes after {@code --scale}; if {@code checked}, a misuse where no Java image has them. */
    private RenderOptions options(boolean checked) {
        boolean sized = given("--width") || given("--height");
        // a window given no size: half the default each way (the default at --scale 0.5), to fit a screen
        Scale scale = window && !sized && !given("--scale") ? new Scale(0.5) : this.scale;
        long scaledWidth = scale.times(width);
        long scaledHeight = scale.times(height);
        boolean empty = scaledWidth < 1 || scaledHeight < 1;
        boolean tooBig = scaledWidth > Integer.MAX_VALUE || scaledHeight > Integer.MAX_VALUE;
        if (checked && (empty || tooBig)) { // the message only for a mistake: formatting loads locale data
            throw new Misuse(String.format(Locale.ROOT, "--scale %s makes the %d×%d image %d×%d pixels; ", scale, width,
                    height, scaledWidth, scaledHeight) + (empty ? "a picture needs at least one pixel each way"
                            : String.format(Locale.ROOT, "Java images hold at most %,d", Integer.MAX_VALUE - 8)));
        }
        return new RenderOptions(scenePaths, output, (int) Math.max(1, Math.min(Integer.MAX_VALUE, scaledWidth)),
                (int) Math.max(1, Math.min(Integer.MAX_VALUE, scaledHeight)), scale, sized, threads, accel, paper,
                samples, stats, !noProgress && StandardStreams.isTerminal(2), clock == null ? 0 : clock);
    }

    private boolean given(String option) {
        return spec.commandLine().getParseResult().hasMatchedOption(option);
    }
}
