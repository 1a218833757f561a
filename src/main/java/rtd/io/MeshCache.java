package rtd.io;

import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The OBJ files a scene's meshes named, each read once for all the frames of an animation (Part III, "Frames
 * on the command line"): a mesh file is the same at every clock, only where the mesh stands may change. Only
 * files read without a mistake are kept; an {@link ObjMesh} is never changed, so frames share it.
 */
final class MeshCache {

    private final Map<Path, ObjMesh> meshes = new ConcurrentHashMap<>();

    /** The mesh read from {@code file} before, or null. */
    ObjMesh get(Path file) {
        return meshes.get(key(file));
    }

    void put(Path file, ObjMesh mesh) {
        meshes.put(key(file), mesh);
    }

    private static Path key(Path file) {
        return file.toAbsolutePath().normalize();
    }
}
