package rtd.io;

import java.util.List;
import java.util.stream.Collectors;

/**
 * Mistakes in a scene file, each a {@link SceneError}. Thrown out of the reader, a scene file that rtd cannot render:
 * it carries every mistake found, up to {@link #MAX_ERRORS}, so that the user can fix them all in one go. Inside the
 * reader, it ends the reading of one statement, whose mistakes the reader records before it goes on; a {@code mesh}
 * whose OBJ file has mistakes fails with all of them, ordered at its {@link #place}, the statement's own place.
 */
public final class SceneException extends Exception {

    /** After this many errors reading stops; more would only scroll the first ones away. */
    public static final int MAX_ERRORS = 20;
    private static final long serialVersionUID = 1L;

    private final transient List<SceneError> errors;
    private final boolean stoppedEarly;
    /** Where the mistakes are ordered among those of the whole scene file. */
    final transient SceneError place;

    /** {@code stoppedEarly}: the file has more errors than these, which the reader did not keep. */
    public SceneException(List<SceneError> errors, boolean stoppedEarly) {
        this(errors.get(0), errors, stoppedEarly);
    }

    SceneException(SceneError error) {
        this(error, List.of(error), false);
    }

    /** Mistakes ordered as if at {@code place}; none for a statement left out for a mistake reported elsewhere. */
    SceneException(SceneError place, List<SceneError> errors) {
        this(place, errors, false);
    }

    private SceneException(SceneError place, List<SceneError> errors, boolean stoppedEarly) {
        super(place.file() + ":" + place.line() + ":" + place.column() + ": " + place.message(), null, false, false);
        this.place = place;
        this.errors = List.copyOf(errors);
        this.stoppedEarly = stoppedEarly;
    }

    public List<SceneError> errors() {
        return errors;
    }

    public String report() {
        return errors.stream().map(SceneError::format).collect(Collectors.joining("\n")) + "\n"
                + (errors.size() == 1 ? "1 error" : errors.size() + " errors")
                + (stoppedEarly ? " shown; the file has more" : "") + "\n";
    }
}
