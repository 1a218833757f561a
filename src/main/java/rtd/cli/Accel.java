package rtd.cli;

/** How rtd finds the object a ray sees: {@code --accel}. */
enum Accel {
    /**
     * The view grid for a scene of {@link Accelerator#GRID_THRESHOLD} objects or more in flat
     * colours, where only the camera's rays are traced; else the bounding volume hierarchy
     * whenever the scene has objects: it tests whole squares of rays at once, which pays even for
     * the paper's two spheres.
     */
    auto,
    /** The paper's loop over every object (Listing 4.3). */
    none,
    /** The bounding volume hierarchy ({@link rtd.accel.Bvh}). */
    bvh,
    /**
     * The view grid ({@link rtd.accel.ViewGrid}) for the camera's rays, the paper's loop for any
     * other ray (shadows, mirrors: slow for a large scene with lights).
     */
    grid
}
