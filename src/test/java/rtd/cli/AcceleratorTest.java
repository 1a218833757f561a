package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
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
    void autoTakesTheImageOfHitsFromAHundredThousandObjectsInFlatColoursWithOneRayAPixel() {
        assertThat(Accelerator.choose(spheres(100_000, false), Accel.auto, 1)).isEqualTo(Accelerator.Kind.IMAGE);
        assertThat(Accelerator.choose(spheres(99_999, false), Accel.auto, 1)).isEqualTo(Accelerator.Kind.GRID);
        assertThat(Accelerator.choose(spheres(1_000, false), Accel.auto, 1)).isEqualTo(Accelerator.Kind.GRID);
        assertThat(Accelerator.choose(spheres(999, false), Accel.auto, 1)).isEqualTo(Accelerator.Kind.BVH);
        assertThat(Accelerator.choose(spheres(250_000, false), Accel.auto, 2)).as("samples")
                .isEqualTo(Accelerator.Kind.GRID);
        assertThat(Accelerator.choose(spheres(250_000, true), Accel.auto, 1)).as("lights")
                .isEqualTo(Accelerator.Kind.GRID_AND_BVH);
    }

    @Test
    void objectsDeepBehindEachOtherAreLeftToTheViewGridWhenBuilt() {
        // 1,000 spheres of radius 0.4 on the points of a square grid, seen 20 pixels a unit: at
        // 40 × 20 pixels (2 × 1 units) no pixel lies in more than one sphere's footprint, and the
        // image of hits serves; 1,000 spheres of radius 30 one behind the other each fill the
        // picture, 1,000 tests a pixel: the view grid.
        assertThat(Accelerator.of(spheres(1_000, false), Accel.image, 40, 20, 1, 1).built().get()).startsWith("image of hits");
        List<IGeometry> large = new ArrayList<>();
        for (int i = 0; i < 1_000; i++) {
            large.add(new Sphere(new Vector3f(20, 12, -i), 30, new Color(i % 256, 0, 0)));
        }
        Scene deep = new Scene(new Color(0, 0, 0), new OrthographicCamera(new Vector3f(20, 12, 50),
                new Vector3f(0, 0, -1), 20), large);
        assertThat(Accelerator.choose(deep, Accel.image, 1)).isEqualTo(Accelerator.Kind.IMAGE);
        assertThat(Accelerator.of(deep, Accel.image, 40, 20, 1, 1).built().get()).startsWith("view grid");
    }

    @Test
    void imageTakesTheViewGridWhereItCannotServeAndAnyOtherChoiceIsKept() {
        assertThat(Accelerator.choose(spheres(3, false), Accel.image, 1)).isEqualTo(Accelerator.Kind.IMAGE);
        assertThat(Accelerator.choose(spheres(3, true), Accel.image, 1)).isEqualTo(Accelerator.Kind.IMAGE_AND_BVH);
        assertThat(Accelerator.choose(spheres(3, false), Accel.image, 3)).isEqualTo(Accelerator.Kind.GRID);
        assertThat(Accelerator.choose(spheres(1_000, false), Accel.grid, 1)).isEqualTo(Accelerator.Kind.GRID);
        assertThat(Accelerator.choose(spheres(1_000, false), Accel.bvh, 1)).isEqualTo(Accelerator.Kind.BVH);
        assertThat(Accelerator.choose(spheres(1_000, false), Accel.none, 1)).isEqualTo(Accelerator.Kind.LOOP);
    }
}
