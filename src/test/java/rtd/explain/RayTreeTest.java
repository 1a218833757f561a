package rtd.explain;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.camera.OrthographicCamera;
import rtd.explain.RayTree.Kind;
import rtd.explain.RayTree.Segment;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Vector3f;
import rtd.scene.Light;
import rtd.scene.Scene;

@DisplayName("A pixel's ray tree as data")
class RayTreeTest {

    /** Looking straight down from (0, 10, 0) at the floor y = 0: the centre pixel of 2 × 2 sees the origin. */
    private static final OrthographicCamera DOWN = new OrthographicCamera(new Vector3f(0, 10, 0),
            new Vector3f(0, -1, 0), 1);
    private static final Plane FLOOR = new Plane(Vector3f.ZERO, new Vector3f(0, 1, 0), Color.fromRGB(0xC8C8C8),
            Material.DEFAULT);

    @Test
    void aFlatScenesTreeIsTheCameraRayToItsHit() {
        Scene flat = new Scene(Color.fromRGB(0), DOWN, List.of(FLOOR));
        List<Segment> segments = RayTree.of(flat, 1, 1, 2, 2).segments();
        assertThat(segments).hasSize(1);
        assertThat(segments.get(0).kind()).isEqualTo(Kind.CAMERA);
        assertThat(segments.get(0).from()).isEqualTo(new Vector3f(0, 10, 0));
        assertThat(segments.get(0).to()).isEqualTo(Vector3f.ZERO);
    }

    @Test
    void aLitPointsShadowRayEndsAtTheLightABlockedOneAtTheBlocker() {
        Light light = new Light(new Vector3f(4, 4, 0), new Rgb(1, 1, 1));
        Scene lit = new Scene(Color.fromRGB(0), DOWN, List.of(FLOOR), List.of(light));
        List<Segment> open = RayTree.of(lit, 1, 1, 2, 2).segments();
        assertThat(open).extracting(Segment::kind).containsExactly(Kind.CAMERA, Kind.SHADOW_LIT);
        assertThat(open.get(1).to()).isEqualTo(light.position());
        assertThat(open.get(1).depth()).isZero();

        // a ball of radius 0.5 at (2, 2, 0), on the way from the origin to the light: the shadow ray meets it
        // 2√2 − 0.5 = 2.3284 from the origin, at (1.6464, 1.6464, 0)
        Sphere ball = new Sphere(new Vector3f(2, 2, 0), 0.5f, Color.fromRGB(0xFF0000));
        Scene shadowed = new Scene(Color.fromRGB(0), DOWN, List.of(FLOOR, ball), List.of(light));
        Segment blocked = RayTree.of(shadowed, 1, 1, 2, 2).segments().get(1);
        assertThat(blocked.kind()).isEqualTo(Kind.SHADOW_BLOCKED);
        assertThat(blocked.to().subtract(new Vector3f(1.6464f, 1.6464f, 0)).magnitude()).isLessThan(1e-3f);
    }

    @Test
    void aMirrorsReflectedRayOpensTheNextBounce() {
        Material mirror = new Material(0.1f, 0.9f, 0.9f, 200f, 0.5f, 0f, 1f);
        Plane shiny = new Plane(Vector3f.ZERO, new Vector3f(0, 1, 0), Color.fromRGB(0xC8C8C8), mirror);
        Scene scene = new Scene(Color.fromRGB(0), DOWN, List.of(shiny), List.of(new Light(new Vector3f(4, 4, 0),
                new Rgb(1, 1, 1))));
        List<Segment> segments = RayTree.of(scene, 1, 1, 2, 2).segments();
        // the ray straight down comes straight back up, hits nothing, and runs on for ever
        Segment reflected = segments.stream().filter(s -> s.kind() == Kind.REFLECTED).findFirst().orElseThrow();
        assertThat(reflected.depth()).isEqualTo(1);
        assertThat(reflected.to()).isNull();
        assertThat(reflected.direction().normalize()).isEqualTo(new Vector3f(0, 1, 0));
    }
}
