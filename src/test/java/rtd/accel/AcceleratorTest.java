package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.accel.Accelerator.Choice;
import rtd.camera.OrthographicCamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Vector3f;
import rtd.scene.Light;
import rtd.scene.Scene;

@DisplayName("What --accel takes for a scene")
class AcceleratorTest {

    private static Scene spheres(int count, boolean lit) {
        List<IGeometry> objects = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            objects.add(new Sphere(new Vector3f(i % 40, i / 40, 0), 0.4f, new Color(i % 256, 0, 0)));
        }
        List<Light> lights = lit ? List.of(new Light(new Vector3f(0, 10, 30), new Rgb(1, 1, 1))) : List.of();
        return new Scene(new Color(0, 0, 0), new OrthographicCamera(new Vector3f(20, 12, 50), new Vector3f(0, 0, -1), 20),
                objects, lights);
    }

    @Test
    void autoTakesTheViewGridWithTheLightGridsWhereThereAreLights() {
        assertThat(Accelerator.choose(spheres(2, false), Choice.auto)).isEqualTo(Accelerator.Kind.GRID);
        assertThat(Accelerator.choose(spheres(1_000, false), Choice.auto)).isEqualTo(Accelerator.Kind.GRID);
        assertThat(Accelerator.choose(spheres(Accelerator.LIGHT_GRIDS_THRESHOLD, true), Choice.auto)).as("lights")
                .isEqualTo(Accelerator.Kind.GRID_BVH_AND_LIGHT_GRIDS);
        assertThat(Accelerator.choose(spheres(0, false), Choice.auto)).as("nothing to build for")
                .isEqualTo(Accelerator.Kind.LOOP);
    }

    @Test
    void autoBuildsNoGridsFromTheLightsForALitSceneOfFewObjects() {
        int few = Accelerator.LIGHT_GRIDS_THRESHOLD - 1;
        assertThat(Accelerator.choose(spheres(few, true), Choice.auto, 40, 20, 1))
                .isEqualTo(Accelerator.Kind.GRID_AND_BVH);
        assertThat(Accelerator.choose(spheres(few, true), Choice.auto)).as("the window's choice too")
                .isEqualTo(Accelerator.Kind.GRID_AND_BVH);
        assertThat(Accelerator.choose(spheres(few + 1, true), Choice.auto, 40, 20, 1))
                .isEqualTo(Accelerator.Kind.GRID_BVH_AND_LIGHT_GRIDS);
        assertThat(Accelerator.choose(spheres(few, true), Choice.grid, 40, 20, 1)).as("grid builds them")
                .isEqualTo(Accelerator.Kind.GRID_BVH_AND_LIGHT_GRIDS);
        assertThat(Accelerator.choose(spheres(few, false), Choice.auto, 40, 20, 1)).as("no lights")
                .isEqualTo(Accelerator.Kind.GRID);
        assertThat(Accelerator.of(spheres(few, true), Choice.auto, 40, 20, 1, 1).built().get())
                .startsWith("view grid of ").contains(", no light grid, and BVH of ");
    }

    @Test
    void anyOtherChoiceIsKept() {
        assertThat(Accelerator.choose(spheres(3, false), Choice.grid)).isEqualTo(Accelerator.Kind.GRID);
        assertThat(Accelerator.choose(spheres(3, true), Choice.grid))
                .isEqualTo(Accelerator.Kind.GRID_BVH_AND_LIGHT_GRIDS);
        assertThat(Accelerator.choose(spheres(3, true), Choice.bvh)).isEqualTo(Accelerator.Kind.BVH);
        assertThat(Accelerator.choose(spheres(3, false), Choice.none)).isEqualTo(Accelerator.Kind.LOOP);
    }

    @Test
    void autoAndGridTakeTheImageOfHitsForAFlatPictureOfManyObjectsAtOneRayAPixel() {
        Scene many = spheres(Accelerator.IMAGE_THRESHOLD, false);
        assertThat(Accelerator.choose(many, Choice.auto, 40, 20, 1)).isEqualTo(Accelerator.Kind.IMAGE);
        assertThat(Accelerator.choose(many, Choice.grid, 40, 20, 1)).isEqualTo(Accelerator.Kind.IMAGE);
        assertThat(Accelerator.choose(many, Choice.auto, 40, 20, 2)).as("samples").isEqualTo(Accelerator.Kind.GRID);
        assertThat(Accelerator.choose(many, Choice.bvh, 40, 20, 1)).isEqualTo(Accelerator.Kind.BVH);
        assertThat(Accelerator.choose(many, Choice.none, 40, 20, 1)).isEqualTo(Accelerator.Kind.LOOP);
        assertThat(Accelerator.choose(spheres(Accelerator.IMAGE_THRESHOLD, true), Choice.auto, 40, 20, 1)).as("lights")
                .isEqualTo(Accelerator.Kind.GRID_BVH_AND_LIGHT_GRIDS);
        assertThat(Accelerator.choose(spheres(Accelerator.IMAGE_THRESHOLD - 1, false), Choice.auto, 40, 20, 1))
                .as("fewer objects").isEqualTo(Accelerator.Kind.GRID);
    }

    @Test
    void objectsThatHideEachOtherDeeplyTakeTheViewGridWhoseRaysTestTheFrontOnes() {
        List<IGeometry> objects = new ArrayList<>();
        for (int i = 0; i < Accelerator.IMAGE_THRESHOLD; i++) { // each covers the whole picture: 100,000 tests a pixel
            objects.add(new Sphere(new Vector3f(20, 12, -i * 0.001f), 30, new Color(i % 256, 0, 0)));
        }
        Scene scene = new Scene(new Color(0, 0, 0),
                new OrthographicCamera(new Vector3f(20, 12, 50), new Vector3f(0, 0, -1), 20), objects);
        assertThat(Accelerator.choose(scene, Choice.auto, 40, 20, 1)).isEqualTo(Accelerator.Kind.GRID);
    }

    @Test
    void statsNameWhatWasBuilt() {
        // 20 pixels a unit: 100 × 20 pixels show x from 17.5 to 22.5 and y from 11.5 to 12.5, the spheres (18|12) to
        // (22|12) of radius 0.4, at pixels 10 ± 8, 30 ± 8, ..., 90 ± 8: the one at 70 in both tiles, 6 entries
        assertThat(Accelerator.of(spheres(Accelerator.IMAGE_THRESHOLD, false), Choice.auto, 100, 20, 1, 2).built().get())
                .isEqualTo("image of hits in 2 tiles of 64 × 64 pixels, 6 entries");
        assertThat(Accelerator.of(spheres(3, false), Choice.bvh, 40, 20, 1, 1).built().get()).startsWith("BVH of ");
        assertThat(Accelerator.of(spheres(3, false), Choice.grid, 40, 20, 1, 1).built().get()).startsWith("view grid of ");
        assertThat(Accelerator.of(spheres(3, true), Choice.grid, 40, 20, 1, 1).built().get())
                .startsWith("view grid of ").contains("light grid").contains("and BVH of ");
    }

    @Test
    void buildsTheBvhOnAThreadOfItsOwnUnlessTheRunHasOneThread() throws Exception {
        Thread[] ran = new Thread[2];
        Accelerator.beside(1).execute(() -> ran[0] = Thread.currentThread());
        CompletableFuture.runAsync(() -> ran[1] = Thread.currentThread(), Accelerator.beside(2))
                .get();
        assertThat(ran[0]).isSameAs(Thread.currentThread());
        assertThat(ran[1]).isNotSameAs(Thread.currentThread());
        assertThat(ran[1].getName()).isEqualTo("rtd-build");
    }
}
