package rtd.accel;

import java.util.List;
import java.util.concurrent.ForkJoinPool;
import rtd.geometry.IGeometry;
import rtd.geometry.Plane;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * Which objects a ray that a flat mirror reflects from the camera's eye may hit, by its
 * direction. A camera ray that meets a mirroring plane at P goes on, mirrored, as if it came
 * straight from the eye's mirror image behind the plane through P: the mirror shows the scene as
 * a second camera standing there would see it. So the objects seen from that point
 * ({@link PointFootprint#leaving}) are sorted into the cells of a square picture, as a
 * {@link ViewGrid} sorts them for the camera, nearest first; a mirrored ray tests the objects of
 * its cell until the next one lies beyond its nearest hit, and the objects without a box
 * ({@link MirrorGridTracer}). A ray the grid does not serve (one whose line passes too far from
 * the mirrored eye, as rays from mirrors seen in mirrors do, or that leaves the picture) goes to
 * the tracer for the others.
 */
final class MirrorGrid {

    /**
     * How far the shader lifts a mirrored ray's origin off the surface, per unit of the hit
     * point's largest coordinate: {@code ε = 1e-4·(1 + max |P|)} ({@code Surface.LIFT}; a test
     * holds the two equal, as this package cannot see the shader's). The lift moves the ray's line
     * up to ε from the mirrored eye; the grid serves rays up to that far off.
     */
    static final float LIFT = 1e-4f;
    /**
     * The widest gap a grid serves, as a share of the eye's height over the mirror: beyond it
     * the footprints would widen by more than a few pixels, and the tree does better.
     */
    private static final double WIDEST_GAP_PER_HEIGHT = 1e-3;

    final PointFootprint footprint;
    /** The cells of the picture, {@code cells.width} pixels square. */
    final ViewGrid cells;

    private MirrorGrid(PointFootprint footprint, ViewGrid cells) {
        this.footprint = footprint;
        this.cells = cells;
    }

    /**
     * The grid of {@code objects}, whose objects with a box lie in {@code box}, seen from the
     * mirror image of {@code eye} in {@code mirror}, on a picture of {@code size × size} pixels;
     * null if the eye lies in the mirror's plane, or the objects are not all well in front of its
     * image ({@link PointFootprint#leaving}).
     */
    static MirrorGrid build(List<IGeometry> objects, float[] box, Vector3f eye, Plane mirror, int size,
            ForkJoinPool pool) {
        Vector3f normal = mirror.normal();
        double nx = normal.x();
        double ny = normal.y();
        double nz = normal.z();
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        Vector3f point = mirror.point();
        // the eye's height over the plane, and its image as far behind it
        double height = ((eye.x() - (double) point.x()) * nx + (eye.y() - (double) point.y()) * ny
                + (eye.z() - (double) point.z()) * nz) / length;
        double twice = 2 * height / length;
        Vector3f image = new Vector3f((float) (eye.x() - twice * nx), (float) (eye.y() - twice * ny),
                (float) (eye.z() - twice * nz));
        double away = Math.abs(height);
        double gap = gap(image, box);
        if (!(gap <= WIDEST_GAP_PER_HEIGHT * away)) {
            return null;
        }
        // a mirrored ray starts on the plane, at least the height from the image: half of it leaves room
        PointFootprint footprint = PointFootprint.leaving(image, box, size, away / 2, gap);
        if (footprint == null) {
            return null;
        }
        // the grid's "pixels" are directions from the image; a ray shows anywhere in its pixel (1)
        ViewGrid cells = new ViewGridBuilder(objects, size, size, pool).build(footprint, null, 1, 1);
        return new MirrorGrid(footprint, cells);
    }

    /**
     * The gap to serve: the shader's lift at the points of the mirror from which a mirrored ray
     * can reach the box. Such a point lies on a line from the image to a point of the box, so no
     * coordinate of it is larger than the image's or the box's; a hundredth more is room for the
     * float rounding of the point and of the image.
     */
    static double gap(Vector3f image, float[] box) {
        double largest = Math.max(Math.abs(image.x()), Math.max(Math.abs(image.y()), Math.abs(image.z())));
        for (float bound : box) {
            largest = Math.max(largest, Math.abs(bound));
        }
        return LIFT * (1 + largest) * 1.01;
    }

    /** The cell of {@code ray}, or −1 if the grid does not serve it. */
    int cellOf(Ray ray) {
        Vector3f origin = ray.origin();
        Vector3f direction = ray.direction();
        int pixel = footprint.pixelLeaving(origin.x(), origin.y(), origin.z(), direction.x(), direction.y(),
                direction.z());
        return pixel < 0 ? -1 : cells.cellOf(pixel % cells.width, pixel / cells.width);
    }

    /** How far the origin of {@code ray} lies from the mirrored eye, rounded up. */
    double originFromX(Ray ray) {
        Vector3f origin = ray.origin();
        return footprint.distanceFrom(origin.x(), origin.y(), origin.z()) * (1 + 1e-9);
    }
}
