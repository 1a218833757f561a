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

    /** One error, which is also where it is ordered. */
    StatementError(SceneError error) {
        this(error, List.of(error));
    }

    /**
     * Several errors, ordered among the scene's errors as if they stood at {@code place}; none for a statement
     * left out because of a mistake reported elsewhere (a broken {@code let} it uses).
     */
    StatementError(SceneError place, List<SceneError> errors) {
        super(errors.isEmpty() ? place.message() : errors.get(0).message(), null, false, false);
        this.place = place;
        this.errors = List.copyOf(errors);
    }
}
