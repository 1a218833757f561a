package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.camera.OrthographicCamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;
import rtd.scene.Scene;

@DisplayName("Shadow rays try the objects that blocked the last ones first")
class RecentBlockersTest {

    /** A row of 1,000 small spheres along x, at y = 0, z = 0, and the tracer that is asked. */
    private final BvhTracer tracer = Bvh.build(row()).newTracer();

    private static Scene row() {
        List<IGeometry> spheres = new ArrayList<>();
        for (int i = 0; i < 1000; i++) {
            spheres.add(new Sphere(new Vector3f(i, 0, 0), 0.25f, new Color(200, 0, 0)));
        }
        return new Scene(new Color(0, 0, 0), new OrthographicCamera(new Vector3f(0, 0, 20), new Vector3f(0, 0, -1), 50),
                spheres);
    }

    /** A shadow ray straight up through the sphere at x, from below it to a light 10 units up. */
    private static Ray upThrough(float x) {
        return new Ray(new Vector3f(x, -5, 0), new Vector3f(0, 15, 0));
    }

    private long nodesVisited() {
        return tracer.work().nodesVisited();
    }

    @Test
    void aRayThatTheLastBlockerBlocksTooIsAnsweredWithoutVisitingANode() {
        assertThat(tracer.blocked(upThrough(500), 15)).isTrue();
        long before = nodesVisited();

        assertThat(tracer.blocked(upThrough(500.1f), 15)).isTrue();

        assertThat(nodesVisited()).isEqualTo(before);
    }

    @Test
    void aBlockerBeyondTheLightDoesNotBlockAndTheTreeIsWalked() {
        assertThat(tracer.blocked(upThrough(500), 15)).isTrue();
        long before = nodesVisited();

        assertThat(tracer.blocked(upThrough(500), 4.75f)).as("the light below the sphere's surface at 4.75").isFalse();

        assertThat(nodesVisited()).as("the tree is walked").isGreaterThan(before);
    }

    @Test
    void fourBlockersAreRememberedSoTwoLightsWithTwoBlockersEachNeedNoWalk() {
        float[] xs = {100, 200, 300, 400};
        for (float x : xs) {
            assertThat(tracer.blocked(upThrough(x), 15)).isTrue();
        }
        long before = nodesVisited();

        for (float x : xs) {
            assertThat(tracer.blocked(upThrough(x + 0.1f), 15)).isTrue();
        }

        assertThat(nodesVisited()).isEqualTo(before);
    }

    @Test
    void aFifthBlockerTakesThePlaceOfTheOldest() {
        for (float x : new float[] {100, 200, 300, 400, 500}) {
            tracer.blocked(upThrough(x), 15);
        }
        long before = nodesVisited();

        tracer.blocked(upThrough(200), 15);
        long afterRemembered = nodesVisited();
        tracer.blocked(upThrough(100), 15);

        assertThat(afterRemembered).as("200 is still remembered").isEqualTo(before);
        assertThat(nodesVisited()).as("100 was forgotten").isGreaterThan(afterRemembered);
    }
}
