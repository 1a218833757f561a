/**
 * The scene file in and the picture out (section 4.1). {@link rtd.io.SceneIO} is the door: it
 * reads a scene and writes a picture through {@code javax.imageio}, all or nothing.
 *
 * <p>Reading, in one pass over the file's bytes: every statement is declared once in the
 * {@link rtd.io.Grammar} table (Part II, "The scene file"); a {@code StatementReader} reads each
 * line's keyword and a {@code GroupReader} its groups into {@code WrittenGroups}, at a shared
 * {@code LineCursor}; the statement's builder asks {@code StatementValues} for checked values and
 * hands what it makes to the {@code SceneContents}; {@code SceneParser} then checks what only the
 * whole file can tell. A {@code mesh}'s OBJ file is read by {@code ObjReader}, its polygons split
 * by {@code EarClipping}. Every mistake becomes a {@link rtd.io.SceneError} with its file, line and
 * column, and all of a file's mistakes one {@link rtd.io.SceneException}. Depends on
 * {@code rtd.scene} and below.
 */
package rtd.io;
