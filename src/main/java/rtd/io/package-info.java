/**
 * The scene file in and the picture out (section 4.1). {@link rtd.io.SceneIO} reads a scene in one pass over
 * its bytes, by the statements of the {@link rtd.io.Grammar}, and writes a picture through
 * {@code javax.imageio}, all or nothing. Every mistake becomes a {@link rtd.io.SceneError} with file, line
 * and column; all of a file's mistakes one {@link rtd.io.SceneException}.
 */
package rtd.io;
