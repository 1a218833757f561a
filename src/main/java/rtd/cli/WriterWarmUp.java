package rtd.cli;

import java.util.concurrent.CompletableFuture;
import rtd.io.ImageFormat;
import rtd.io.ImageWriting;

/**
 * The one warm-up of {@code javax.imageio} per JVM ({@link ImageWriting#warmUp}), and after it
 * of the reader and the renderer ({@link RendererWarmUp}), started as early as possible:
 * {@link Main} starts it for PNG before the command line is even parsed, so that it runs on a
 * spare core while picocli starts and the scene is read. The one piece of state that outlives
 * a call: the warm-up is per JVM, as what it loads is.
 */
final class WriterWarmUp {

    private static CompletableFuture<Void> started;

    private WriterWarmUp() {
    }

    /**
     * Starts the warm-up for {@code format}, unless one has started: the writers share most of
     * what they load (the imaging classes and the registry of writers), so any one helps.
     */
    static synchronized CompletableFuture<Void> start(ImageFormat format) {
        if (started == null) {
            started = ImageWriting.warmUp(format, RendererWarmUp::run);
        }
        return started;
    }
}
