/**
 * The scene file in and the picture out (section 4.1): {@link rtd.io.SceneIO} reads a scene
 * (every statement declared once in {@link rtd.io.Grammar}; Part II, "The scene file"), OBJ meshes
 * (Part II, "Geometry") and writes the picture through {@code javax.imageio}. Every mistake in a file
 * becomes a {@link rtd.io.SceneException} with its file, line and column. Depends on
 * {@code rtd.scene} and below.
 */
package rtd.io;
