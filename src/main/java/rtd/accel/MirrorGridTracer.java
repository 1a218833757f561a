package rtd.accel;

import java.util.List;
import rtd.geometry.Hit;
import rtd.math.Ray;
import rtd.render.Tracer;

/**
 * Answers the rays that flat mirrors reflect from the camera's eye through {@link MirrorGrids}: such
 * a ray tests the objects of its cell, nearest first by their distance from the eye's image X, and
 * those without a box. Its cell holds every object it can hit; the depth test does not depend on the
 * order of the tests; and it stops only where the next object lies farther from X than its origin
 * does plus its nearest hit, so that no hit on that object or any after it can be nearer. So the
 * answer is the paper's loop's. Any ray whose line passes X as a mirrored one does is served the
 * same way, whatever made it; every other ray, and every shadow ray, goes to the tracer for the
 * others. Not thread-safe: one per thread.
 */
final class MirrorGridTracer extends PointGridTracer {

    private final MirrorGrids.Grid[] grids;

    MirrorGridTracer(List<MirrorGrids.Grid> grids, Tracer others) {
        super(grids.stream().map(MirrorGrids.Grid::cells).toList(), others, "mirror grids");
        this.grids = grids.toArray(MirrorGrids.Grid[]::new);
    }

    @Override
    public Hit nearestHit(Ray ray) {
        for (int g = 0; g < grids.length; g++) {
            int cell = grids[g].cellOf(ray);
            if (cell >= 0) {
                rays++;
                ViewGrid cells = grids[g].cells();
                NearestHit hit = hits[g];
                hit.start(ray);
                hit.testUnbounded();
                hit.testPlacesNearestFirst(cells.places, cells.cellStart[cell], cells.cellStart[cell + 1],
                        cells.nearest, grids[g].originFromImage(ray));
                return hit.hit(ray);
            }
        }
        return others.nearestHit(ray);
    }
}
