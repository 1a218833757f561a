package rtd.io;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

/**
 * Finds and reads the OBJ file a {@code mesh} names, relative to the scene's folder (Part II, "Geometry"). A
 * file that cannot be read is an error at the path; mistakes inside it are located in it, each naming the
 * scene's line.
 */
final class MeshFiles {

    /** Larger files do not fit in one Java array. */
    private static final long MAX_SIZE = Integer.MAX_VALUE - 8;

    private MeshFiles() {
    }

    /** The mesh in the OBJ file that group {@code g} of the statement names. */
    static ObjMesh read(StatementValues values, int g) throws StatementError {
        SourceText scene = values.source();
        String written = values.name(g);
        Path file;
        String shown;
        try {
            Path path = Path.of(written);
            file = scene.folder().resolve(path);
            shown = path.isAbsolute() ? written : shownName(scene.name(), path);
        } catch (InvalidPathException e) {
            throw values.errorAtValue(g, 0, "'" + written + "' is not a file path here: " + e.getReason(), null);
        }
        byte[] bytes;
        try {
            bytes = readFile(file);
        } catch (IOException e) {
            throw values.errorAtValue(g, 0, "cannot read the mesh file '" + shown + "': " + reason(e),
                    e instanceof NoSuchFileException && written.indexOf('\\') >= 0 ? Hints.forWindowsPath(written)
                            : "a mesh's path is relative to the folder of the scene file");
        }
        ObjMesh mesh;
        try {
            try (SourceText obj = new SourceText(shown, bytes)) {
                mesh = ObjReader.read(obj);
            }
        } catch (SceneException e) {
            String usedBy = "this file is used by " + scene.name() + ":" + values.line();
            List<SceneError> errors = e.errors().stream().map(error -> new SceneError(error.file(), error.line(),
                    error.column(), error.message(), error.sourceLine(),
                    error.help() == null ? usedBy : error.help() + "; " + usedBy)).toList();
            throw new StatementError(values.placeOfValue(g, 0), errors);
        }
        if (mesh.count() == 0) {
            // else the scene would lose the mesh without a word, and the warning of an empty picture would blame the camera
            throw values.errorAtValue(g, 0, "the mesh file '" + shown + "' has no faces: rtd found no 'f' line in it",
                    "rtd skips the lines of an OBJ file other than v, vn and f, so a misspelt 'F' or 'face' line is "
                            + "skipped too; a mesh needs at least one face");
        }
        return mesh;
    }

    /** The OBJ file's name as the user knows it: the scene's name, with the path in place of its file name. */
    private static String shownName(String sceneName, Path path) {
        try {
            return Path.of(sceneName).resolveSibling(path).toString();
        } catch (InvalidPathException e) {
            return path.toString();
        }
    }

    private static byte[] readFile(Path file) throws IOException {
        if (Files.isDirectory(file)) {
            throw new FileSystemException(file.toString(), null, "it is a folder, not a file");
        }
        if (Files.exists(file) && !Files.isRegularFile(file)) {
            // a device or a pipe: it might never end
            throw new FileSystemException(file.toString(), null, "it is not a regular file");
        }
        if (Files.exists(file) && Files.size(file) > MAX_SIZE) {
            throw new FileSystemException(file.toString(), null, "it is larger than 2 GB");
        }
        return SceneFileReader.readWhole(file); // not Files.readAllBytes: it keeps a buffer as large as the file
    }

    /** Why a file could not be read, in words for a person. */
    private static String reason(IOException e) {
        if (e instanceof NoSuchFileException) {
            return "no such file";
        }
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof FileSystemException failure && failure.getReason() != null) {
            return failure.getReason().toLowerCase(Locale.ROOT);
        }
        return e.getMessage() != null ? e.getMessage() : "an input error";
    }
}
