package rtd.accel;

import java.util.List;
import java.util.concurrent.ForkJoinPool;
import rtd.geometry.IGeometry;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.Light;

/**
 * Which objects a shadow ray towards one light may hit, by the direction it comes from: the
 * objects seen from the light ({@link PointFootprint}) sorted into the cells of a square picture,
 * as a {@link ViewGrid} sorts them for the camera. A shadow ray tests the objects of its cell
 * and the objects without a box, and stops at the first hit before the light
 * ({@link LightGridTracer}). A ray that the grid does not serve (one that does not end at the
 * light, runs too far, or comes from outside the picture) goes to the tracer for the others.
 */
final class LightGrid {

    final PointFootprint footprint;
    /** The cells of the picture, {@code cells.width} pixels square. */
    final ViewGrid cells;
    /**
     * How far short of the light the shader's shadow rays end ({@link Light#clearance}): a ray is
     * served as if it ran on to the light, where the grid's geometry is exact, and its hits are
     * still only those nearer than its own end.
     */
    private final float clearance;

    private LightGrid(PointFootprint footprint, ViewGrid cells, float clearance) {
        this.footprint = footprint;
        this.cells = cells;
        this.clearance = clearance;
    }

    /**
     * The grid of {@code objects} seen from {@code light}, whose objects with a box lie in
     * {@code box}, on a picture of {@code size × size} pixels; null if the light lies too near or
     * among them ({@link PointFootprint#around}).
     */
    static LightGrid build(List<IGeometry> objects, float[] box, Light light, int size, ForkJoinPool pool) {
        PointFootprint footprint = PointFootprint.around(light.position(), box, size);
        if (footprint == null) {
            return null;
        }
        // no camera: the grid's "pixels" are directions from the light; a ray shows anywhere in its pixel (1)
        ViewGrid cells = new ViewGridBuilder(objects, size, size, pool).build(footprint, null, 1, 1);
        return new LightGrid(footprint, cells, light.clearance());
    }

    /**
     * How far from the light a hit of a served ray of length {@code distance} can lie, at most:
     * {@code distance + c + g}, as its origin lies at most that far (c the clearance) and its hits
     * lie between the origin and the end, within the gap g of the light ({@link PointFootprint});
     * a second g and a millionth are room for rounding past the end.
     */
    float farthestHit(float distance) {
        return (float) (((double) distance + clearance + 2 * footprint.gap()) * (1 + 1e-6));
    }

    /**
     * The cell of a shadow ray, whose question is whether it hits anything nearer than
     * {@code distance}, or −1 if the grid does not serve it: served if, run on by the clearance,
     * it ends at the light.
     */
    int cellOf(Ray ray, float distance) {
        Vector3f origin = ray.origin();
        Vector3f direction = ray.direction();
        double length = Math.sqrt((double) direction.x() * direction.x() + (double) direction.y() * direction.y()
                + (double) direction.z() * direction.z());
        double toLight = (double) distance + clearance;
        double along = toLight / length;
        int pixel = footprint.pixelOf(origin.x(), origin.y(), origin.z(), origin.x() + along * direction.x(),
                origin.y() + along * direction.y(), origin.z() + along * direction.z(), toLight);
        return pixel < 0 ? -1 : cells.cellOf(pixel % cells.width, pixel / cells.width);
    }
}
