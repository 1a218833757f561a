package rtd.cli;

/** How rtd finds the object a ray sees: {@code --accel}. */
enum Accel {
    /**
     * For a scene of {@link Accelerator#IMAGE_THRESHOLD} objects or more, the image of hits where
     * it is drawn in flat colours (no light) with one ray a pixel and the image's limits allow
     * ({@link rtd.accel.HitImage#build}); for one of {@link Accelerator#GRID_THRESHOLD} or more
     * otherwise the view grid (with the bounding volume hierarchy for its
     * shadow and mirror rays if it has lights); else the hierarchy whenever the scene has objects:
     * it tests whole squares of rays at once, which pays even for the paper's two spheres.
     */
    auto,
    /** The paper's loop over every object (Listing 4.3). */
    none,
    /** The bounding volume hierarchy ({@link rtd.accel.Bvh}). */
    bvh,
    /**
     * The view grid ({@link rtd.accel.ViewGrid}) for the camera's rays, and in a scene with lights
     * the light grids and mirror grids ({@link rtd.accel.LightGrids}, {@link rtd.accel.MirrorGrids})
     * and the hierarchy for the shadow and mirror rays they do not serve.
     */
    grid,
    /**
     * The image of hits ({@link rtd.accel.HitImage}) for the camera's rays, found object by object
     * before the render, where one ray a pixel is drawn; else the view grid; and in a scene with
     * lights the light grids, the mirror grids and the hierarchy for the other rays.
     */
    image
}
