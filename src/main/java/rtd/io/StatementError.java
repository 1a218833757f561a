package rtd.io;

import java.util.List;

/**
 * Ends the reading of one statement with its mistakes; the reader records them and goes on. A {@code mesh}
 * whose OBJ file has mistakes fails with all of them, ordered at {@link #place}, the statement's own place.
 */
final class StatementError extends Exception {

    private static final long serialVersionUID = 1L;
    final transient SceneError place;
    final transient List<SceneError> errors;

    StatementError(SceneError error) {
        this(error, List.of(error));
    }

    /** Errors ordered as if at {@code place}; none for a statement left out for a mistake reported elsewhere. */
    StatementError(SceneError place, List<SceneError> errors) {
        super(errors.isEmpty() ? place.message() : errors.get(0).message(), null, false, false);
        this.place = place;
        this.errors = List.copyOf(errors);
    }
}
