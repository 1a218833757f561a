package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import rtd.camera.OrthographicCamera;
import rtd.geometry.Hit;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.Scene;

/**
 * A hit whose distance is not a number never wins, in the tree as in the paper's loop
 * ({@code distance < nearest} is false for NaN). A sphere so large that its test overflows
 * reports t = +∞, and on a ray with a zero direction component the distance is then 0 · ∞ = NaN.
 */
class NotANumberDistanceTest {

    private static final Scene SCENE = new Scene(new Color(0, 0, 0),
            new OrthographicCamera(new Vector3f(0, 0, 30), new Vector3f(0, 0, -1), 60),
            List.of(new Sphere(new Vector3f(0, 0, 0), 1e20f, new Color(200, 0, 0)),
                    new Sphere(new Vector3f(0, 0, 5), 6, new Color(0, 0, 200))));

    @Test
    void aHitAtANotANumberDistanceLosesToARealOneAsInThePapersLoop() {
        Ray ray = new Ray(new Vector3f(0.5f, 0.25f, 30), new Vector3f(0, 0, -1));
        Hit loop = SCENE.nearestHit(ray);

        Hit tree = Bvh.build(SCENE).newTracer().nearestHit(ray);

        assertThat(loop.index()).isEqualTo(1);
        assertThat(tree.index()).isEqualTo(loop.index());
        assertThat(tree.t()).isEqualTo(loop.t());
    }

    @Test
    void aHitAtANotANumberDistanceAloneIsNoHitAsInThePapersLoop() {
        Scene alone = new Scene(SCENE.ambient(), SCENE.camera(), List.of(SCENE.objects().get(0)));
        Ray ray = new Ray(new Vector3f(0.5f, 0.25f, 30), new Vector3f(0, 0, -1));

        assertThat(alone.nearestHit(ray)).isNull();
        assertThat(Bvh.build(alone).newTracer().nearestHit(ray)).isNull();
    }
}
