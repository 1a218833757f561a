package rtd.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine;
import rtd.accel.Accelerator;
import rtd.explain.PixelExplanation;
import rtd.io.SceneException;
import rtd.render.ParallelRenderer;
import rtd.render.RenderProgress;
import rtd.render.RenderResult;
import rtd.scene.Scene;
import rtd.view.View;
import rtd.view.ViewPicture;
import rtd.view.ViewShader;

/**
 * What the teaching options ask: {@code --explain X,Y} prints what rtd does for one pixel in the paper's terms,
 * {@code --view KIND} draws what the rays did, {@code --export-pov} writes the scene for POV-Ray, {@code --watch}
 * renders again whenever the scene changes. Each is null (or false) if not given.
 */
record TeachingRun(String explain, View view, Path exportPov, boolean watch) {

    private static final Pattern PIXEL = Pattern.compile("\\s*(\\d{1,9})\\s*,\\s*(\\d{1,9})\\s*");

    /** Runs what takes the picture's place ({@code --explain}, {@code --view}, {@code --watch}); else null. */
    Integer run(RenderOptions options, CommandLine commandLine, PrintWriter err) throws SceneException, FileError {
        String replacing = replacingOption();
        if (replacing != null || exportPov != null) { // one scene file: one answer, read once
            if (explain != null && explain.matches("\\s*\\d{1,9}\\s*")) { // --explain 300 400 reads 400 as a scene
                Path number = options.scenes().stream().filter(p -> p.toString().matches("\\d{1,9}")
                        && !Files.exists(p)).findFirst().orElse(null);
                Misuse.refuse(number != null, "--explain takes the pixel as X,Y with a comma, and '" + number + "' "
                        + "was read as a scene file; did you mean --explain " + explain.strip() + "," + number + "?");
            }
            String option = replacing != null ? replacing : "--export-pov";
            Misuse.oneSceneFile(option, options.scenes());
            Misuse.refuse(options.scene().toString().equals("-"), option + " needs a scene file; it "
                    + "cannot work on standard input ('-')");
        }
        if (watch) {
            Misuse.refuse(OutputTarget.DASH.equals(options.output()), "--watch writes the picture again at each "
                    + "save, which cannot go to standard output ('-o -'); give a file, such as -o out.png");
            return SceneWatcher.forCommandLine(commandLine, options.scene(), err).run();
        }
        Misuse.refuse(explain != null && view != null, "--explain and --view each take the place of "
                + "the picture; give one of them");
        if (explain == null && view == null) {
            return null;
        }
        int[] pixel = explain == null ? null : pixel(options);
        if (view != null) {
            Memory.checkImageFits(options.width(), options.height(), options.scale());
        }
        // every file is planned before the scene is read and anything is written, every misuse before a file's problem
        OutputTarget povTarget;
        try {
            povTarget = planExport(options);
        } catch (FileError e) {
            try {
                if (view != null) {
                    viewTarget(options);
                }
            } catch (FileError later) {
                // the export's comes first
            }
            throw e;
        }
        OutputTarget viewTarget = view != null ? viewTarget(options) : null;
        if (pixel != null && options.output() != null) {
            err.println("rtd: note: --explain prints its steps and writes no picture; -o is not used");
        }
        if (pixel != null && options.stats()) {
            err.println("rtd: note: --explain follows one ray and times nothing; --stats is not used");
        }
        StatsReport stats = new StatsReport();
        Scene scene = SceneRun.read(SceneSource.of(options.scene()), null, options, povTarget,
                ProgressDisplay.start(false, err), stats);
        if (pixel == null) {
            return view(scene, viewTarget, options, stats, err);
        }
        if (options.paper() && !scene.lights().isEmpty()) { // explain what --paper draws
            err.println("rtd: note: --paper draws as the paper does, in flat colours: the scene's lights are not used, "
                    + "and the explanation follows the flat picture");
            scene = new Scene(scene.ambient(), scene.camera(), scene.objects());
        }
        explain(scene, pixel[0], pixel[1], options, commandLine.getOut());
        return 0;
    }

    /** The option that takes the picture's place ({@code --explain}, {@code --view}, {@code --watch}), or null. */
    String replacingOption() {
        return watch ? "--watch" : explain != null ? "--explain" : view != null ? "--view" : null;
    }

    /** Where {@code --export-pov} goes, as {@code -o}, but only to a .pov name, also behind a link; null without it. */
    OutputTarget planExport(RenderOptions options) throws FileError {
        if (exportPov == null) {
            return null;
        }
        String name = exportPov.getFileName() == null ? "" : exportPov.getFileName().toString();
        Misuse.refuse(exportPov.toString().equals("-"), "--export-pov writes a file, not standard "
                + "output ('-'); give a name that ends in .pov, such as scene.pov");
        Misuse.refuse(name.indexOf('"') >= 0, "--export-pov '" + exportPov + "': a name with a double "
                + "quote cannot be given to POV-Ray; choose one without"); // the folder is cd's
        String base = name.contains(".") ? name.substring(0, name.lastIndexOf('.')) : name;
        Misuse.refuse(!endsInPov(exportPov), "--export-pov writes a POV-Ray scene, and its name must end in .pov; '"
                + exportPov + "' does not: give a name such as " + (base.isEmpty() ? "scene" : base) + ".pov");
        OutputTarget target = OutputTarget.of(exportPov, options.scene(), "--export-pov");
        Misuse.refuse(target.kind() == OutputTarget.Kind.REPLACE && !endsInPov(target.file()), "'"
                + exportPov + "' leads to '" + target.file() + "', whose name does not end in .pov; --export-pov "
                + "replaces only a POV-Ray scene");
        return target;
    }

    private static boolean endsInPov(Path file) {
        return file.getFileName() != null && file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".pov");
    }

    /** Where the view goes: {@code -o}, or beside the scene as {@code scene-KIND.png}; checked as a picture's is. */
    private OutputTarget viewTarget(RenderOptions options) throws FileError {
        Path byDefault = JobPlanner.defaultOutput(options.scene(), "-" + view);
        Misuse.refuse(OutputTarget.DASH.equals(options.output()), "--view writes its picture to a "
                + "file; -o - (standard output) is for the rendered picture only: give a file name, such as "
                + byDefault.getFileName());
        OutputTarget target = OutputTarget.of(options.output() != null ? options.output() : byDefault, options.scene(),
                "-o");
        JobPlanner.format(target); // a format no writer knows: a misuse, before the scene is read
        return target;
    }

    /** {@code --view KIND}: what the camera's rays did ({@link View}), traced on the path the picture would take. */
    private int view(Scene scene, OutputTarget target, RenderOptions options, StatsReport stats, PrintWriter err)
            throws FileError {
        if (options.samples() > 1) {
            err.println("rtd: note: a view takes one ray per pixel; --samples is not used");
        }
        Accelerator accelerator = Accelerator.of(scene, options.engine(), options.width(), options.height(), 1,
                options.threads());
        stats.endPhase("build");
        ViewShader shader = new ViewShader(view, scene.objects());
        RenderResult raw = ParallelRenderer.render(scene.camera(), accelerator.tracers(), tracer -> shader,
                options.width(), options.height(), 1, options.threads(), new RenderProgress());
        stats.endPhase("render"); // drawing the view's legend belongs to making the picture: the write
        ViewPicture picture = ViewPicture.of(view, raw.image(), scene);
        target.write(picture.picture(), JobPlanner.format(target), null, done -> { });
        err.print("rtd: " + picture.report().replace("\n", "\n     ").stripTrailing() + "\n");
        stats.endPhase("write");
        if (options.stats()) { // a view runs on every thread, also the paper's loop
            err.print(stats.format(scene, accelerator, raw.work(), options.threads(), target.spelt()));
            err.flush();
        }
        return 0;
    }

    /** The pixel of {@code --explain X,Y} in the picture; a misuse (exit 2) that names the image's size if none. */
    private int[] pixel(RenderOptions options) {
        int width = options.width();
        int height = options.height();
        String range = String.format("0 ≤ X < %d and 0 ≤ Y < %d (the image is %d × %d)", width, height, width, height);
        Matcher matcher = PIXEL.matcher(explain);
        Misuse.refuse(!matcher.matches(), "--explain '" + explain + "': give the pixel as X,Y, two "
                + "whole numbers with " + range);
        int x = Integer.parseInt(matcher.group(1));
        int y = Integer.parseInt(matcher.group(2));
        Misuse.refuse(x >= width || y >= height, "--explain " + x + "," + y + ": the pixel lies "
                + "outside the image; choose " + range);
        return new int[] {x, y};
    }

    private static void explain(Scene scene, int x, int y, RenderOptions options, PrintWriter out) {
        out.println("rtd --explain " + x + "," + y + ": pixel (" + x + ", " + y + ") of the " + options.width() + " × "
                + options.height() + " picture of " + options.scene());
        out.println("(every number is the renderer's own float, written as the shortest decimal that reads back "
                + "as it)");
        if (options.samples() > 1) {
            out.println("(with --samples " + options.samples() + " the picture's pixel is the mean of "
                    + options.samples() * options.samples()
                    + " rays; this is the ray through its corner, --samples 1)");
        }
        out.println();
        out.print(PixelExplanation.of(scene, x, y, options.width(), options.height()));
        out.flush();
    }
}
