package rtd.scene;

import java.awt.image.BufferedImage;
import java.util.List;
import rtd.camera.ICamera;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.geometry.Intersection;
import rtd.image.Color;
import rtd.math.Ray;

/**
 * A scene: a background colour, a camera, the objects and the lights (paper, sections 4.1 and
 * 4.3; the lights are Part II's).
 *
 * <p>This is where the paper's algorithm (Listing 3.1) lives, in the paper's shape:
 * {@link #render} makes a ray for every pixel (ray generation, section 3.2.1) and
 * {@link #trace} colours it from {@link #nearestHit}, which tests it against every object
 * (intersection test, section 3.2.2) and keeps the nearest (depth test, section 3.2.3, Listing
 * 4.3). It is the plain reference, and {@code --paper} runs it; {@code rtd.render} and
 * {@code rtd.accel} hold faster paths that call the same tests and draw the same pixels.
 *
 * @param ambient the colour of every pixel whose ray hits nothing
 * @param camera  makes the rays
 * @param objects the objects, in the order of the scene file; on a tie the first wins
 * @param lights  the point lights; none: the paper's flat colours
 */
public record Scene(Color ambient, ICamera camera, List<IGeometry> objects, List<Light> lights) {

    /** Keeps unmodifiable copies of the objects and lights, so that a scene never changes. */
    public Scene {
        objects = List.copyOf(objects);
        lights = List.copyOf(lights);
    }

    /** A scene without lights, as the paper's: drawn in flat colours. */
    public Scene(Color ambient, ICamera camera, List<IGeometry> objects) {
        this(ambient, camera, objects, List.of());
    }

    /** Listing 4.2: one ray per pixel, traced, and its colour set on the image. */
    public BufferedImage render(int width, int height) {
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int x = 0; x < width; ++x) {
            for (int y = 0; y < height; ++y) {
                Ray ray = camera.generateRay(x, y, width, height);
                img.setRGB(x, y, trace(ray).getRGB());
            }
        }
        return img;
    }

    /**
     * Listing 4.3 with flat colours: the colour of the nearest object the ray hits, or the
     * background. A patterned object's colour is its pattern's at the hit ({@link Hit#colour}).
     */
    public Color trace(Ray ray) {
        Hit hit = nearestHit(ray);
        return hit == null ? ambient : hit.colour(ray.direction());
    }

    /**
     * Listing 4.3: the intersection test with every object, then the depth test
     * ({@link DepthTest}): the object whose hit point P lies nearest to the ray's origin O
     * ({@code |P − O|}) wins, and on a tie the object that comes first in the file. Any ray will
     * do, not only a camera's. Returns {@code null} if the ray hits nothing.
     */
    public Hit nearestHit(Ray ray) {
        float distance = Float.POSITIVE_INFINITY;
        Hit hit = null;
        for (int i = 0; i < objects.size(); i++) {
            IGeometry object = objects.get(i);
            Intersection intersection = object.intersect(ray);
            if (intersection.happened()) {
                float currentDistance = DepthTest.distance(intersection.contactCoord(), ray.origin());
                if (DepthTest.nearer(currentDistance, i, distance, hit == null ? 0 : hit.index())) {
                    distance = currentDistance;
                    hit = new Hit(object, i, intersection.t(), currentDistance, intersection.contactCoord());
                }
            }
        }
        return hit;
    }
}
