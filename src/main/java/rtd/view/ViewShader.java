package rtd.view;

import java.util.List;
import rtd.geometry.Hit;
import rtd.geometry.IGeometry;
import rtd.image.Rgb;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.render.HitBuffer;
import rtd.render.RayBundle;
import rtd.render.Shader;

/**
 * The "shader" of a debug view: for each camera ray a number, not a colour, in the picture's
 * int. The renderer moves ints without looking at them, so a view renders on every path the
 * picture does (all threads, the paper's loop, every {@code --accel}); {@link ViewPicture} turns the
 * numbers into colours once the scale of the whole picture is known.
 *
 * <ul>
 * <li>cost: the ray's count of intersection tests;</li>
 * <li>depth: the bits of the float {@code |P − O|} (infinite: no hit);</li>
 * <li>normal and id: the colour itself, which needs no scale.</li>
 * </ul>
 */
public final class ViewShader implements Shader {

    private final View view;
    private final List<IGeometry> objects;

    /** The shader of {@code view} for a scene of these objects. */
    public ViewShader(View view, List<IGeometry> objects) {
        this.view = view;
        this.objects = objects;
    }

    @Override
    public int rgb(RayBundle rays, HitBuffer hits, int i) {
        return switch (view) {
            case cost -> hits.tests(i);
            case depth -> Float.floatToRawIntBits(hits.distance(i));
            case normal -> normalColour(hits.hit(i, rays, objects), rays.ray(i));
            case id -> ViewColours.id(hits.index(i));
        };
    }

    /** Views are numbers, never averaged: the view renders one ray per pixel. */
    @Override
    public Rgb colour(RayBundle rays, HitBuffer hits, int i) {
        throw new UnsupportedOperationException("a view takes one ray per pixel");
    }

    /** {@code (N + 1)/2}, a channel per axis; no hit: black. */
    static int normalColour(Hit hit, Ray ray) {
        if (hit == null) {
            return 0;
        }
        Vector3f n = hit.normal(ray.direction());
        return new Rgb((n.x() + 1) / 2, (n.y() + 1) / 2, (n.z() + 1) / 2).toColor().getRGB();
    }
}
