package rtd.accel;

import java.util.List;
import rtd.math.Ray;
import rtd.render.Tracer;

/**
 * Answers the shadow rays that {@link LightGrids} serve, the same as the paper's loop; every other
 * ray goes to the tracer for the others. Not thread-safe: one per thread.
 */
final class LightGridTracer extends PointGridTracer {

    private final LightGrids.Grid[] grids;

    LightGridTracer(List<LightGrids.Grid> grids, Tracer others) {
        super(grids.stream().map(LightGrids.Grid::cells).toList(), others, "light grids");
        this.grids = grids.toArray(LightGrids.Grid[]::new);
    }

    @Override
    public boolean blocked(Ray ray, float distance) {
        for (int g = 0; g < grids.length; g++) {
            int cell = grids[g].cellOf(ray, distance);
            if (cell >= 0) {
                rays++;
                ViewGrid cells = grids[g].cells();
                NearestHit hit = hits[g];
                hit.start(ray);
                hit.limitTo(distance);
                hit.testUnbounded();
                hit.testPlacesUntilHit(cells.places, cells.cellStart[cell], cells.cellStart[cell + 1], cells.nearest,
                        grids[g].farthestHit(distance));
                return hit.best() >= 0;
            }
        }
        return others.blocked(ray, distance);
    }
}
