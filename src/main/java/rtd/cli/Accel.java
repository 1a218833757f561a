package rtd.cli;

/** How rtd finds the object a ray sees: {@code --accel}. */
enum Accel {
    /** As {@link #grid}; the hierarchy alone where the grid cannot serve the camera. */
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
