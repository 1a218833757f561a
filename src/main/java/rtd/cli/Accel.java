package rtd.cli;

/** How rtd finds the object a ray sees: {@code --accel}. */
enum Accel {
    /**
     * The view grid for a scene of {@link Accelerator#GRID_THRESHOLD} objects or more (with the
     * bounding volume hierarchy for its shadow and mirror rays if it has lights); else the
     * hierarchy whenever the scene has objects: it tests whole squares of rays at once, which
     * pays even for the paper's two spheres.
     */
    auto,
    /** The paper's loop over every object (Listing 4.3). */
    none,
    /** The bounding volume hierarchy ({@link rtd.accel.Bvh}). */
    bvh,
    /**
     * The view grid ({@link rtd.accel.ViewGrid}) for the camera's rays, and in a scene with lights
     * the hierarchy for the shadow and mirror rays.
     */
    grid
}
