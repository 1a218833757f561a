package rtd.accel;

import java.util.List;
import java.util.concurrent.ForkJoinPool;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.geometry.Plane;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.Tracer;
import rtd.scene.Scene;

/**
 * For the rays a flat mirror reflects from the camera's eye, a grid seen from the eye's mirror
 * image: the mirrored rays' counterpart of the camera's {@link ViewGrid}. A camera ray that meets a
 * mirroring plane at P goes on, mirrored, as if it came straight from the eye's image X behind the
 * plane through P: the mirror shows the scene as a second camera standing at X would see it. So
 * the objects seen from X ({@link PointFootprint#leaving}) are sorted into the cells of a square
 * picture, nearest to X first; a mirrored ray tests the objects of its cell until the next lies
 * beyond its nearest hit, and those without a box ({@link MirrorGridTracer}). Its cell holds every
 * object it can hit, so the answer is the paper's loop's. A ray that no grid serves (one whose line
 * passes too far from X, as rays from mirrors seen in mirrors do, or that leaves the picture) goes
 * to the tracer for the others. Not in the paper or Part II.
 */
public final class MirrorGrids extends PointGrids<MirrorGrids.Grid> {

    /** The widest gap served, as a share of the eye's height over the mirror: the tree does better beyond. */
    private static final double WIDEST_GAP_PER_HEIGHT = 1e-3;

    /** One mirror's grid: the footprints seen from the eye's image, and the cells of its picture. */
    record Grid(PointFootprint footprint, ViewGrid cells) implements PointGrids.Grid {

        /**
         * The grid of {@code objects}, whose objects with a box lie in {@code box}, seen from the
         * mirror image of {@code eye} in {@code mirror}, on a picture of {@code size × size} pixels;
         * null if the eye lies in the mirror's plane, or the objects are not all well in front of its
         * image ({@link PointFootprint#leaving}).
         */
        static Grid build(List<IGeometry> objects, float[] box, Vector3f eye, Plane mirror, int size,
                ForkJoinPool pool) {
            Vector3f n = mirror.normal();
            double length = Math.sqrt((double) n.x() * n.x() + (double) n.y() * n.y() + (double) n.z() * n.z());
            Vector3f q = mirror.point();
            double height = ((eye.x() - (double) q.x()) * n.x() + (eye.y() - (double) q.y()) * n.y()
                    + (eye.z() - (double) q.z()) * n.z()) / length;
            double twice = 2 * height / length; // the image lies as far behind the plane as the eye before it
            Vector3f image = new Vector3f((float) (eye.x() - twice * n.x()), (float) (eye.y() - twice * n.y()),
                    (float) (eye.z() - twice * n.z()));
            double gap = gap(image, box);
            if (!(gap <= WIDEST_GAP_PER_HEIGHT * Math.abs(height))) {
                return null;
            }
            // a mirrored ray starts on the plane, at least the height from the image: half of it leaves room
            PointFootprint footprint = PointFootprint.leaving(image, box, size, Math.abs(height) / 2, gap);
            if (footprint == null) {
                return null;
            }
            return new Grid(footprint, PointGrids.cells(objects, footprint, size, pool));
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
            return Hit.LIFT * (1 + largest) * 1.01; // the shader lifts a mirrored ray this far off X
        }

        /** The cell of {@code ray}, or −1 if the grid does not serve it. */
        int cellOf(Ray ray) {
            Vector3f o = ray.origin();
            Vector3f d = ray.direction();
            int pixel = footprint.pixelLeaving(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
            return pixel < 0 ? -1 : cells.cellOf(pixel % cells.width, pixel / cells.width);
        }

        /** How far the origin of {@code ray} lies from the eye's image, rounded up. */
        double originFromImage(Ray ray) {
            Vector3f o = ray.origin();
            return footprint.distanceFrom(o.x(), o.y(), o.z()) * (1 + 1e-9);
        }
    }

    /** No grid: every mirrored ray goes to the tracer for the others. */
    public static final MirrorGrids NONE = new MirrorGrids(List.of());

    private MirrorGrids(List<Grid> grids) {
        super(grids);
    }

    /**
     * The grids of {@code scene}'s mirroring planes (material {@code reflective > 0}), for a
     * {@code width × height} picture with {@code samples²} rays a pixel, built with {@code threads}
     * threads; none without lights (flat colours follow no mirrored ray) or without the perspective
     * camera (the orthographic one has no eye to mirror). A mirror serves only the rays from its own
     * part of the image: the picture's side is half the image's, √(width · height) · samples / 2.
     * The grids together hold copies of at most {@link #MOST_PACKED} objects.
     */
    public static MirrorGrids build(Scene scene, int width, int height, int samples, int threads) {
        List<IGeometry> objects = scene.objects();
        float[] box = boxOf(objects);
        if (scene.lights().isEmpty() || !(scene.camera() instanceof PerspectiveCamera camera) || box == null) {
            return NONE;
        }
        List<Plane> mirrors = objects.stream().filter(object -> object instanceof Plane plane
                && plane.material().reflective() > 0).map(Plane.class::cast).toList();
        int size = side(Math.sqrt((double) width * height) * samples / 2);
        return new MirrorGrids(build(mirrors, objects.size(), threads, MOST_PACKED,
                (mirror, pool) -> Grid.build(objects, box, camera.position(), mirror, size, pool)));
    }

    /** A new tracer for the mirrored rays these grids serve, and {@code others} for every other ray; one per thread. */
    public Tracer newTracer(Tracer others) {
        return grids().isEmpty() ? others : new MirrorGridTracer(grids(), others);
    }
}
