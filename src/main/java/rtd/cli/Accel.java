package rtd.cli;

/** How rtd finds the object a ray sees: {@code --accel}. */
enum Accel {
    /**
     * The view grid for a large scene in flat colours seen by the orthographic camera, where
     * only the camera's parallel rays are traced; else the bounding volume hierarchy whenever
     * the scene has objects: it tests whole squares of parallel rays at once, which pays even for
     * the paper's two spheres.
     */
    auto,
    /** The paper's loop over every object (Listing 4.3). */
    none,
    /** The bounding volume hierarchy ({@link rtd.accel.Bvh}). */
    bvh,
    /**
     * The view grid ({@link rtd.accel.ViewGrid}) for the orthographic camera's rays, the paper's
     * loop for any other ray; the hierarchy if the camera is not orthographic.
     */
    grid
}
