package rtd.window;

import java.util.ArrayList;
import java.util.List;
import rtd.camera.ICamera;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.explain.RayTree;
import rtd.math.Vector3f;

/**
 * A pixel's {@link RayTree} drawn into the picture: each ray as a line of image coordinates, where the camera would
 * show its points. The projection undoes the camera's ray generation (Listing 4.1 and the perspective camera): a ray
 * through image point {@code (x, y)} passes through the world points that project to it.
 *
 * <ul>
 * <li>orthographic: {@code x = w/2 + zoom·(P − pos)·u}, {@code y = h/2 + zoom·(P − pos)·v};</li>
 * <li>perspective: with {@code d = P − pos} and {@code z = d·forward}, {@code x = w/2 + f·(d·u)/z},
 *     {@code y = h/2 + f·(d·v)/z}; a line is cut where it passes behind the eye ({@code z} below a small share of the
 *     scene's size), which the camera cannot show.</li>
 * </ul>
 * ({@code w/2} and {@code h/2} are whole numbers, as the cameras take them.) A ray that hits nothing is drawn far along
 * its direction.
 */
record RayTreeProjection(ICamera camera, int width, int height) {

    /** One ray of the tree in the picture, from (x0, y0) to (x1, y1); {@code ends} whether it ends at a point. */
    record Line(RayTree.Kind kind, double x0, double y0, double x1, double y1, boolean ends) {
    }

    /** How far, in lengths of the scene around the camera, a ray that hits nothing is drawn. */
    private static final float FAR = 1e4f;

    /** The tree's rays as lines in the picture; a ray wholly behind a perspective camera's eye is left out. */
    List<Line> lines(RayTree tree) {
        float size = (float) tree.segments().stream().filter(segment -> segment.to() != null)
                .mapToDouble(segment -> segment.to().subtract(camera.position()).magnitude()).reduce(1, Math::max);
        List<Line> lines = new ArrayList<>();
        for (RayTree.Segment segment : tree.segments()) {
            Vector3f from = segment.from();
            Vector3f to = segment.to() != null ? segment.to()
                    : from.add(segment.direction().normalize().multiply(FAR * size));
            Line line = line(segment, from, to, size);
            if (line != null) {
                lines.add(line);
            }
        }
        return lines;
    }

    /** The image point of world point {@code p}: {@code [x, y]}; for a perspective camera p must lie ahead. */
    double[] project(Vector3f p) {
        if (camera instanceof OrthographicCamera ortho) {
            Vector3f d = p.subtract(ortho.position());
            return new double[] {width / 2 + (double) ortho.zoom() * d.dot(ortho.widthVector()),
                height / 2 + (double) ortho.zoom() * d.dot(ortho.heightVector())};
        }
        PerspectiveCamera perspective = (PerspectiveCamera) camera;
        Vector3f d = p.subtract(perspective.position());
        double z = d.dot(perspective.forward());
        double f = perspective.focalLength(width);
        return new double[] {width / 2 + f * d.dot(perspective.widthVector()) / z,
            height / 2 + f * d.dot(perspective.heightVector()) / z};
    }

    private Line line(RayTree.Segment segment, Vector3f from, Vector3f to, float size) {
        boolean ends = segment.to() != null;
        if (camera instanceof PerspectiveCamera perspective) {
            float near = size * 1e-4f;
            float zFrom = from.subtract(perspective.position()).dot(perspective.forward());
            float zTo = to.subtract(perspective.position()).dot(perspective.forward());
            if (zFrom < near && zTo < near) {
                return null;
            }
            Vector3f cut = from.add(to.subtract(from).multiply((near - zFrom) / (zTo - zFrom)));
            if (zFrom < near) {
                from = cut;
            } else if (zTo < near) {
                to = cut;
                ends = false;
            }
        }
        double[] a = project(from);
        double[] b = project(to);
        return new Line(segment.kind(), a[0], a[1], b[0], b[1], ends);
    }
}
