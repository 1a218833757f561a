package rtd.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.IntConsumer;
import java.util.function.IntSupplier;
import java.util.regex.Pattern;
import java.util.zip.CRC32;
import picocli.CommandLine;

/**
 * {@code --watch}: renders, then again whenever the scene file or a mesh it names changes, until Ctrl-C; each render a
 * whole run of rtd, so a broken edit prints its errors and leaves the last good picture. Files are compared by size,
 * time and checksum (a save within one clock tick is seen), and a change is rendered once they have settled.
 */
final class SceneWatcher {

    static final long POLL_MILLIS = 200;
    /** Longer than the steps of one save (empty the file, write it), even on a busy machine. */
    static final long SETTLE_MILLIS = 100;
    private static final long CHECKSUM_LIMIT = 16L << 20;
    private static final Pattern MESH = Pattern.compile("(?m)^[ \\t]*mesh[ \\t]*:[ \\t]*\\(([^)|\\r\\n]+)\\)");

    private final Path scene;
    private final IntSupplier render;
    private final PrintWriter err;
    private final long pollMillis;
    private IntConsumer rendered = code -> { };
    private volatile boolean stopped;
    private boolean anyGood;

    SceneWatcher(Path scene, IntSupplier render, PrintWriter err, long pollMillis) {
        this.scene = scene;
        this.render = render;
        this.err = err;
        this.pollMillis = pollMillis;
    }

    /** A watcher whose renders run {@code commandLine}'s own arguments again, without {@code --watch}. */
    static SceneWatcher forCommandLine(CommandLine commandLine, Path scene, PrintWriter err) {
        String[] args = withoutWatch(commandLine.getParseResult().originalArgs());
        return new SceneWatcher(scene, () -> {
            CommandLine fresh = RtdCommand.commandLine();
            fresh.setOut(commandLine.getOut());
            fresh.setErr(commandLine.getErr());
            return fresh.execute(args);
        }, err, POLL_MILLIS);
    }

    static String[] withoutWatch(List<String> args) {
        return args.stream().filter(arg -> !arg.equals("--watch")).toArray(String[]::new);
    }

    /** Tells {@code listener} each render's exit code (tests wait on it). */
    SceneWatcher onRendered(IntConsumer listener) {
        this.rendered = listener;
        return this;
    }

    void stop() {
        stopped = true;
    }

    /** Renders, then again at each change, until stopped or interrupted; the last render's exit code. */
    int run() {
        Map<Path, String> seen = fingerprints();
        int code = renderOnce();
        if (code == 2) {
            return code; // a mistake on the command line: no edit of the scene can mend it
        }
        int meshes = seen.size() - 1;
        err.println("rtd: watching " + scene + (meshes == 0 ? "" : " and " + meshes + " mesh file" + (meshes == 1 ? ""
                : "s")) + " for changes; Ctrl-C stops");
        err.flush();
        try {
            while (!stopped && !Thread.currentThread().isInterrupted()) {
                Thread.sleep(pollMillis);
                Map<Path, String> now = fingerprints();
                if (!now.equals(seen)) {
                    Map<Path, String> before;
                    do { // until the files look the same twice in a row: a save caught halfway shows errors
                        before = now;
                        Thread.sleep(Math.max(pollMillis, SETTLE_MILLIS));
                        now = fingerprints();
                    } while (!now.equals(before) && !stopped);
                    err.println("rtd: " + changed(seen, now) + " changed: rendering again");
                    seen = now;
                    err.flush();
                    code = renderOnce();
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return code;
    }

    /** The first file that changed; the scene if a mesh statement went away. */
    private Path changed(Map<Path, String> before, Map<Path, String> now) {
        return now.keySet().stream().filter(file -> !now.get(file).equals(before.get(file))).findFirst().orElse(scene);
    }

    private int renderOnce() {
        int code = render.getAsInt();
        if (code == 1) {
            err.println(anyGood ? "rtd: the last good picture stays; fix the scene and save it again"
                    : "rtd: no picture yet; fix the scene and save it again");
            err.flush();
        }
        anyGood |= code == 0;
        rendered.accept(code);
        return code;
    }

    /** The scene file and each mesh file it names, with what each looks like now. */
    private Map<Path, String> fingerprints() {
        Map<Path, String> prints = new LinkedHashMap<>();
        prints.put(scene, fingerprint(scene));
        try {
            if (Files.size(scene) <= CHECKSUM_LIMIT) {
                MESH.matcher(Files.readString(scene, StandardCharsets.UTF_8)).results()
                        .map(mesh -> scene.toAbsolutePath().getParent().resolve(mesh.group(1).strip()).normalize())
                        .forEach(mesh -> prints.put(mesh, fingerprint(mesh)));
            }
        } catch (IOException | RuntimeException e) {
            // unreadable or not UTF-8: the render says what is wrong; watch the scene alone
        }
        return prints;
    }

    private static String fingerprint(Path file) {
        try {
            long size = Files.size(file);
            String print = size + "@" + Files.getLastModifiedTime(file).toMillis();
            if (size <= CHECKSUM_LIMIT) {
                CRC32 crc = new CRC32();
                crc.update(Files.readAllBytes(file));
                print += "#" + crc.getValue();
            }
            return print;
        } catch (IOException e) {
            return "missing";
        }
    }
}
