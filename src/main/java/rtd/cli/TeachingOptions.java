package rtd.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Spec;
import rtd.explain.PixelExplanation;
import rtd.io.ImageFormat;
import rtd.io.SceneError;
import rtd.io.SceneException;
import rtd.io.SceneIO;
import rtd.scene.Scene;
import rtd.view.View;

/**
 * The teaching options (a picocli mixin of {@link RtdCommand}): {@code --explain X,Y} prints
 * what rtd does for one pixel in the paper's terms, {@code --view KIND} draws what the rays did,
 * {@code --export-pov FILE.pov} writes the scene for POV-Ray, and {@code --watch} renders again
 * whenever the scene changes. They live here, apart from the command's own code, and read its
 * other options from picocli's model ({@link RenderSettings}).
 */
public final class TeachingOptions {

    @Spec(Spec.Target.MIXEE)
    private CommandSpec command;

    @Option(names = "--explain", paramLabel = "X,Y", description = "instead of a picture, print what rtd does for "
            + "pixel (X, Y), step by step in the paper's terms: the ray, each object's intersection test, the depth "
            + "test and the colour (with lights: each light's terms and the reflected and refracted rays)")
    private String explain;

    @Option(names = "--view", paramLabel = "KIND", description = "instead of the picture, draw what the rays did: "
            + "cost (intersection tests per ray, a heat map with its scale), depth (|P - O| in grey, near bright), "
            + "normal (the normal as colour), id (a colour per object); default output SCENE-KIND.png")
    private View view;

    @Option(names = "--export-pov", paramLabel = "FILE.pov", converter = OutputFileName.class, description = "also write the "
            + "scene as a POV-Ray 3.7 scene that draws the same picture; its first lines give the povray command")
    private Path exportPov;

    @Option(names = "--watch", description = "after the first render, render again whenever the scene file (or a mesh "
            + "it uses) changes, until Ctrl-C; a broken edit prints its errors and keeps the last good picture")
    private boolean watch;

    /**
     * Runs what the teaching options ask for instead of the picture ({@code --explain},
     * {@code --view}, {@code --watch}), with the export first if one was asked for too; or returns
     * {@code null} if rtd is to render as usual (with the export that {@link #planExport} plans).
     */
    Integer run(PrintWriter err) throws SceneException {
        RenderSettings settings = RenderSettings.of(command);
        CommandLine commandLine = command.commandLine();
        if (watch || explain != null || view != null || exportPov != null) {
            checkOneSceneFile(settings, commandLine);
        }
        if (watch) {
            return SceneWatcher.forCommandLine(commandLine, settings.scene(), err).run();
        }
        if (explain != null && view != null) {
            throw new ParameterException(commandLine, "--explain and --view each take the place of the picture; give one "
                    + "of them");
        }
        PixelArgument pixel = explain == null ? null : PixelArgument.parse(explain, settings.width(), settings.height(), commandLine);
        if (pixel == null && view == null) {
            return null;
        }
        if (view != null) {
            ImageSize.check(commandLine, settings.width(), settings.height());
        }
        // Every file is planned before the scene is read and before anything is written, every
        // mistake on the command line before a file's problem.
        FileError refused = null;
        OutputTarget povTarget = null;
        OutputTarget viewTarget = null;
        try {
            povTarget = planExport();
        } catch (FileError e) {
            refused = e;
        }
        try {
            viewTarget = pixel == null ? viewTarget(settings, commandLine) : null;
        } catch (FileError e) {
            refused = refused == null ? e : refused;
        }
        ImageFormat viewFormat = viewTarget == null ? null : JobPlanner.format(viewTarget, commandLine);
        if (refused != null) {
            err.println("rtd: " + refused.getMessage());
            return 1;
        }
        if (pixel != null && settings.output() != null) { // once every misuse has had its say
            err.println("rtd: note: --explain prints its steps and writes no picture; -o is not used");
        }
        if (pixel != null && settings.stats()) {
            err.println("rtd: note: --explain follows one ray and times nothing; --stats is not used");
        }
        PhaseTimer timer = new PhaseTimer();
        Scene scene = readScene(settings, err);
        if (scene == null) {
            return 1;
        }
        timer.endPhase("parse");
        if (povTarget != null) {
            try {
                err.println(PovExportRun.write(scene, povTarget, settings.width(), settings.height()));
                err.flush();
            } catch (FileError e) {
                err.println("rtd: " + e.getMessage());
                return 1;
            }
            timer.endPhase("export");
        }
        if (pixel != null && settings.paper() && !scene.lights().isEmpty()) { // explain what --paper draws
            err.println("rtd: note: --paper draws as the paper does, in flat colours: the scene's lights are not used, "
                    + "and the explanation follows the flat picture");
            scene = new Scene(scene.ambient(), scene.camera(), scene.objects(), List.of());
        }
        return pixel != null ? explain(scene, pixel, settings, commandLine.getOut())
                : view(scene, viewTarget, viewFormat, settings, timer, err);
    }

    /**
     * Where {@code --export-pov} goes, planned before anything is read or written; null without
     * it. A mistake in its name is thrown as misuse; a file that may not be written is a {@link FileError}.
     */
    OutputTarget planExport() throws FileError {
        return exportPov == null ? null : PovExportRun.plan(exportPov, RenderSettings.of(command).scene(), command.commandLine());
    }

    private static int explain(Scene scene, PixelArgument pixel, RenderSettings settings, PrintWriter out) {
        out.println("rtd --explain " + pixel.x() + "," + pixel.y() + ": pixel (" + pixel.x() + ", " + pixel.y() + ") of the "
                + settings.width() + " × " + settings.height() + " picture of " + settings.scene());
        out.println("(every number is the renderer's own float, written as the shortest decimal that reads back as it)");
        if (settings.samples() > 1) {
            out.println("(with --samples " + settings.samples() + " the picture's pixel is the mean of "
                    + settings.samples() * settings.samples() + " rays; this is the ray through its corner, --samples 1)");
        }
        out.println();
        out.print(PixelExplanation.of(scene, pixel.x(), pixel.y(), settings.width(), settings.height()));
        out.flush();
        return 0;
    }

    private int view(Scene scene, OutputTarget target, ImageFormat format, RenderSettings settings, PhaseTimer timer,
            PrintWriter err) {
        if (settings.samples() > 1) {
            err.println("rtd: note: a view takes one ray per pixel; --samples is not used");
        }
        ViewRun.Result result = ViewRun.render(scene, view, settings, timer);
        try {
            ViewRun.write(result, target, format, err);
        } catch (IOException e) {
            err.println("rtd: cannot write '" + target.spelt() + "': " + FileProblems.reason(e));
            return 1;
        }
        timer.endPhase("write");
        if (settings.stats()) {
            err.print(StatsReport.format(timer, scene, result.accelerator(), result.render().work(),
                    settings.threads(), target.spelt())); // a view runs on every thread, also the paper's loop
            err.flush();
        }
        return 0;
    }

    /** Where the view goes: {@code -o}, or beside the scene under the view's name; checked as a picture's is. */
    private OutputTarget viewTarget(RenderSettings settings, CommandLine commandLine) throws FileError {
        if (OutputTarget.DASH.equals(settings.output())) {
            throw new ParameterException(commandLine, "--view writes its picture to a file; -o - (standard output) "
                    + "is for the rendered picture only: give a file name, such as "
                    + ViewRun.defaultOutput(settings.scene(), view).getFileName());
        }
        Path spelt = settings.output() != null ? settings.output() : ViewRun.defaultOutput(settings.scene(), view);
        return JobPlanner.target(spelt, settings.scene(), "-o", commandLine);
    }

    /**
     * The teaching options work on one scene file: several would need several explanations, views
     * or exports under one name, and standard input can be neither watched nor read twice.
     */
    private void checkOneSceneFile(RenderSettings settings, CommandLine commandLine) {
        String option = watch ? "--watch" : explain != null ? "--explain" : view != null ? "--view" : "--export-pov";
        if (settings.scenes().size() > 1) {
            throw new ParameterException(commandLine, option + " works on one scene file, but " + settings.scenes().size()
                    + " were given; run rtd once for each");
        }
        if (settings.scene().toString().equals("-")) {
            throw new ParameterException(commandLine, option + " needs a scene file; it cannot work on standard input ('-')");
        }
    }

    /** The scene, or null after saying why it cannot be read; mistakes in it are thrown, for the command's report. */
    private static Scene readScene(RenderSettings settings, PrintWriter err) throws SceneException {
        Path path = settings.scene();
        try {
            List<SceneError> warnings = new ArrayList<>();
            Scene scene = settings.scale().of(SceneIO.readScene(path, warnings));
            for (SceneError warning : warnings) {
                err.print(warning.formatAsWarning());
            }
            err.flush();
            return scene;
        } catch (IOException e) {
            err.println("rtd: cannot read the scene file '" + path + "': " + FileProblems.reason(e));
            return null;
        }
    }
}
