package rtd.io;

import java.util.List;
import java.util.stream.Collectors;

/**
 * A scene file that rtd cannot render: it carries every {@link SceneError} found, up to {@link #MAX_ERRORS}, so
 * that the user can fix them all in one go.
 */
public final class SceneException extends Exception {

    /** After this many errors reading stops; more would only scroll the first ones away. */
    public static final int MAX_ERRORS = 20;
    private static final long serialVersionUID = 1L;

    private final transient List<SceneError> errors;
    private final boolean stoppedEarly;

    /** {@code stoppedEarly}: the file has more errors than these, which the reader did not keep. */
    public SceneException(List<SceneError> errors, boolean stoppedEarly) {
        super(errors.get(0).file() + ":" + errors.get(0).line() + ":" + errors.get(0).column() + ": "
                + errors.get(0).message(), null, false, false);
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
