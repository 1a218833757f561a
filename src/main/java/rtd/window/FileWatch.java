package rtd.window;

/**
 * Tells the window when the scene file, or a mesh it uses, has been saved: the command line's watcher, the one
 * {@code --watch} renders again with.
 */
@FunctionalInterface
public interface FileWatch {

    /** Starts watching; {@code changed} runs on the watcher's thread after each save, until the result is closed. */
    AutoCloseable start(Runnable changed);
}
