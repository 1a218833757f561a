package rtd.cli;

/** How rtd finds the object a ray sees: {@code --accel}. */
enum Accel {
    /**
     * For a scene of {@link Accelerator#GRID_THRESHOLD} objects or more the view grid (with the
     * light grids and the bounding volume hierarchy for the shadow and reflected rays if it has
     * lights); else the hierarchy whenever the scene has objects: it tests whole squares of rays
     * at once, which pays even for the paper's two spheres.
     */
    auto,
    /** The paper's loop over every object (Listing 4.3). */
    none,
    /** The bounding volume hierarchy ({@link rtd.accel.Bvh}) for every ray. */
    bvh,
    /**
     * The view grid ({@link rtd.accel.ViewGrid}) for the camera's rays, and in a scene with lights
     * the light grids ({@link rtd.accel.LightGrids}) for the shadow rays they serve and the
     * hierarchy for the rest.
     */
    grid
}
