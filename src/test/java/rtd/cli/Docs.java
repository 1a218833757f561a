package rtd.cli;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** The catalogue of messages, docs/errors.md, for tests that check a message is in it word for word. */
final class Docs {

    private Docs() {
    }

    /** The catalogue's text. */
    static String errors() {
        try {
            return Files.readString(Path.of("docs", "errors.md"));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The first line of {@code err}, with {@code dir} and the path separator after it taken out, as the catalogue shows it. */
    static String firstLine(String err, Path dir) {
        return err.lines().findFirst().orElse("").replace(dir + "/", "");
    }
}
