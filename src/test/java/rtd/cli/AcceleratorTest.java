package rtd.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.camera.OrthographicCamera;
import rtd.cli.Accelerator.Choice;
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
        assertThat(Accelerator.choose(spheres(2, true), Choice.auto)).as("lights").isEqualTo(Accelerator.Kind.GRID_AND_BVH);
        assertThat(Accelerator.choose(spheres(0, false), Choice.auto)).as("nothing to build for")
                .isEqualTo(Accelerator.Kind.LOOP);
    }

    @Test
    void anyOtherChoiceIsKept() {
        assertThat(Accelerator.choose(spheres(3, false), Choice.grid)).isEqualTo(Accelerator.Kind.GRID);
        assertThat(Accelerator.choose(spheres(3, true), Choice.grid)).isEqualTo(Accelerator.Kind.GRID_AND_BVH);
        assertThat(Accelerator.choose(spheres(3, true), Choice.bvh)).isEqualTo(Accelerator.Kind.BVH);
        assertThat(Accelerator.choose(spheres(3, false), Choice.none)).isEqualTo(Accelerator.Kind.LOOP);
    }

    @Test
    void statsNameWhatWasBuilt() {
        assertThat(Accelerator.of(spheres(3, false), Choice.bvh, 40, 20, 1, 1).built().get()).startsWith("BVH of ");
        assertThat(Accelerator.of(spheres(3, false), Choice.grid, 40, 20, 1, 1).built().get()).startsWith("view grid of ");
        assertThat(Accelerator.of(spheres(3, true), Choice.grid, 40, 20, 1, 1).built().get())
                .startsWith("view grid of ").contains("light grid").contains("and BVH of ");
    }
}
