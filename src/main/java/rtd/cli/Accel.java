package rtd.cli;

/** How rtd finds the object a ray sees: {@code --accel}. */
enum Accel {
    /**
     * The bounding volume hierarchy whenever the scene has objects: it tests whole squares of
     * parallel rays at once, which pays even for the paper's two spheres.
     */
    auto,
    /** The paper's loop over every object (Listing 4.3). */
    none,
    /** The bounding volume hierarchy ({@link rtd.accel.Bvh}). */
    bvh;

    /** Whether to trace a scene of {@code objects} objects with the hierarchy. */
    boolean usesBvh(int objects) {
        return this == bvh || this == auto && objects > 0;
    }
}
