package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.render.RenderResult;
import rtd.geometry.IGeometry;
import rtd.image.Color;
import rtd.scene.Scene;
import rtd.testing.MixedScenes;
import rtd.testing.RandomScenes;
import rtd.testing.Renders;
import rtd.testing.Scenes;

@DisplayName("The bounding volume hierarchy")
class BvhTest {

    @Test
    void holdsEveryObjectOnceAlsoWhenItOutgrowsItsFirstRoomForNodes() {
        // Threes of spheres far apart make leaves of fewer than four objects on average: more
        // nodes than half the objects, the room NodeBlocks starts with.
        Random random = new Random(3);
        List<IGeometry> objects = new ArrayList<>();
        for (int group = 0; group < 20_000; group++) {
            float x = 100 * (group % 28);
            float y = 100 * (group / 28 % 28);
            float z = 100 * (group / 784);
            for (int k = 0; k < 3; k++) {
                objects.add(Scenes.sphere(x + 10 * random.nextFloat(), y + 10 * random.nextFloat(),
                        z + 10 * random.nextFloat(), 0.5f + random.nextInt(3), 0x102030));
            }
        }
        Bvh bvh = Bvh.build(new Scene(Color.BLACK, Scenes.frontCamera(5000, 1), objects));
        assertThat(bvh.nodeCount()).isGreaterThan(objects.size() / 2);
        assertThat(Arrays.stream(bvh.leaves.fileOrder).sorted().toArray())
                .isEqualTo(java.util.stream.IntStream.range(0, objects.size()).toArray());
    }

    @Test
    void holdsEachObjectInOneLeafOrLeavesItOutAsTheTwinOfOneItHolds() {
        Scene scene = RandomScenes.generate(11, 20_000);
        Bvh bvh = Bvh.build(scene);
        Set<Integer> inLeaves = new HashSet<>();
        for (int node = 0; node < bvh.nodeCount(); node++) {
            if (bvh.nodes[2 * node + 1] != Bvh.INNER) {
                for (int i = bvh.nodes[2 * node]; i < bvh.nodes[2 * node] + bvh.nodes[2 * node + 1]; i++) {
                    assertThat(inLeaves.add(bvh.leaves.fileOrder[i])).as("object %d in two leaves", bvh.leaves.fileOrder[i]).isTrue();
                }
            }
        }
        Set<Object> heldShapes = new HashSet<>();
        for (int object : inLeaves) {
            heldShapes.add(KnownShapes.twinKey(scene.objects().get(object)));
        }
        for (int object = 0; object < scene.objects().size(); object++) {
            assertThat(heldShapes.contains(KnownShapes.twinKey(scene.objects().get(object)))).as("object %d held", object).isTrue();
        }
        assertThat(inLeaves.size()).as("twins are few among random spheres").isGreaterThan(19_000);
    }

    @Test
    void countsEveryTestOfAMixedTreeUnderItsKindOfObject() {
        Scene scene = MixedScenes.generate(12, 400);
        BvhTracer tracer = Bvh.build(scene).newTracer();
        Random random = new Random(12);
        for (int r = 0; r < 500; r++) {
            tracer.nearestHit(MixedScenes.ray(random, scene));
        }
        Map<String, Long> counted = tracer.work().testsByKind();
        long sum = counted.values().stream().mapToLong(Long::longValue).sum();

        assertThat(sum).isEqualTo(tracer.testsRun());
        assertThat(counted).containsKeys("box", "sphere", "triangle");
        assertThat(counted.get("box")).isPositive();
        assertThat(counted.get("triangle")).isPositive();
    }

    @Test
    void countsTheTestsOfALeafOfSeveralKindsEachUnderItsOwnKind() {
        // a sphere and a box side by side make one leaf; a ray that reaches it tests both
        List<IGeometry> objects = List.of(Scenes.sphere(0, 0, 0, 1, 0x102030),
                new rtd.geometry.Box(new rtd.math.Vector3f(3, -1, -1), new rtd.math.Vector3f(5, 1, 1),
                        Color.fromRGB(0x808080), rtd.geometry.Material.DEFAULT));
        BvhTracer tracer = Bvh.build(new Scene(Color.BLACK, Scenes.frontCamera(20, 1), objects)).newTracer();
        tracer.nearestHit(new rtd.math.Ray(new rtd.math.Vector3f(0, 0, 10), new rtd.math.Vector3f(0, 0, -1)));

        assertThat(tracer.work().testsByKind()).containsEntry("sphere", 1L).containsEntry("box", 1L);
        assertThat(tracer.testsRun()).isEqualTo(2);
    }

    @Test
    void aSceneWithoutObjectsShowsOnlyTheAmbientColour() {
        Scene empty = new Scene(Color.fromRGB(0x123456), Scenes.frontCamera(20, 10), List.of());
        RenderResult result = Renders.parallel(empty, 40, 30, 2, true);
        assertThat(result.image().rgb(20, 15)).isEqualTo(0x123456);
        assertThat(result.work().intersectionTests()).isZero();
    }

    @Test
    void testsAFewObjectsPerRayWhereThePapersLoopTestsAll() {
        Scene scene = RandomScenes.generate(3, 20_000);
        RenderResult withBvh = Renders.parallel(scene, 160, 120, 2, true);
        RenderResult paper = Renders.parallel(scene, 16, 12, 2, false);
        assertThat(paper.work().testsPerRay()).isEqualTo(20_000.0);
        assertThat(withBvh.work().testsPerRay()).isLessThan(200.0);
        assertThat(withBvh.work().nodesPerRay()).isPositive().isLessThan(400.0);
    }

    @Test
    void manyCopiesOfOneSphereCostOneTestAndTheFirstInTheFileStillWins() {
        java.util.List<rtd.geometry.IGeometry> objects = new java.util.ArrayList<>();
        objects.add(Scenes.sphere(6, 0, 0, 1, 0x0000FF));
        for (int i = 0; i < 5_000; i++) {
            objects.add(Scenes.sphere(0, 0, 0, 2, i)); // 5,000 twins of different colours
        }
        objects.add(Scenes.sphere(0, 0, 3, 0.5f, 0xFF0000)); // nearer than the twins where it covers them
        Scene scene = new Scene(Color.BLACK, Scenes.frontCamera(20, 20), objects);
        RenderResult withBvh = Renders.parallel(scene, 160, 120, 2, true);
        assertThat(withBvh.image().rgb()).isEqualTo(Renders.paper(scene, 160, 120));
        assertThat(withBvh.image().rgb(80, 60)).isEqualTo(0xFF0000);
        assertThat(withBvh.image().rgb(80 - 30, 60)).isEqualTo(0); // the first twin, colour 0
        assertThat(withBvh.work().testsPerRay()).isLessThan(3.0);
    }
}
