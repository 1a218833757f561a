package rtd.accel;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.accel.Accelerator.StructureCache;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.IGeometry;
import rtd.geometry.Material;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Vector3f;
import rtd.scene.Light;
import rtd.scene.Scene;

@DisplayName("What one frame built that the next uses again")
class StructureCacheTest {

    private static final Color RED = new Color(255, 0, 0);

    /** Frame {@code i}: the camera at x = i, a sphere at x = {@code sphereX}, the light at x = {@code lightX}. */
    private static Scene frame(int i, float sphereX, float lightX, IGeometry... more) {
        List<IGeometry> objects = new ArrayList<>(List.of(new Sphere(new Vector3f(sphereX, 0, 0), 1, RED)));
        objects.addAll(List.of(more));
        return new Scene(new Color(0, 0, 0), PerspectiveCamera.lookingAt(new Vector3f(i, 2, 20), new Vector3f(0, 0, 0),
                60), objects, List.of(new Light(new Vector3f(lightX, 30, 0), new Rgb(1, 1, 1))));
    }

    @Test
    void aMovingCameraOverObjectsEqualByValueKeepsTheBvhAndTheLightGrids() {
        StructureCache kept = new StructureCache();
        Scene first = frame(0, 0, 0);
        Scene second = frame(1, 0, 0); // new records, equal by value
        assertThat(second.objects()).isNotSameAs(first.objects());
        assertThat(kept.bvh(second)).isSameAs(kept.bvh(first));
        assertThat(kept.lightGrids(second, 40, 20, 1, 1)).isSameAs(kept.lightGrids(first, 40, 20, 1, 1));
    }

    @Test
    void aMovedObjectRebuildsBothAndAMovedLightOnlyTheLightGrids() {
        StructureCache kept = new StructureCache();
        Scene first = frame(0, 0, 0);
        var bvh = kept.bvh(first);
        var grids = kept.lightGrids(first, 40, 20, 1, 1);
        Scene lightMoved = frame(1, 0, 5);
        assertThat(kept.bvh(lightMoved)).isSameAs(bvh);
        assertThat(kept.lightGrids(lightMoved, 40, 20, 1, 1)).isNotSameAs(grids);
        Scene sphereMoved = frame(2, 0.5f, 5);
        assertThat(kept.bvh(sphereMoved)).isNotSameAs(bvh);
        assertThat(kept.lightGrids(sphereMoved, 40, 20, 1, 1)).isNotSameAs(grids);
    }

    @Test
    void anotherPictureSizeRebuildsTheLightGrids() {
        StructureCache kept = new StructureCache();
        var grids = kept.lightGrids(frame(0, 0, 0), 40, 20, 1, 1);
        assertThat(kept.lightGrids(frame(1, 0, 0), 40, 20, 1, 1)).isSameAs(grids);
        assertThat(kept.lightGrids(frame(1, 0, 0), 80, 40, 1, 1)).isNotSameAs(grids);
    }

    /** A triangle is no record: one made anew is not known to be the same, so the BVH is built again. */
    @Test
    void aShapeThatIsNoRecordIsKeptOnlyAsTheSameObject() {
        StructureCache kept = new StructureCache();
        Triangle triangle = triangle();
        var bvh = kept.bvh(frame(0, 0, 0, triangle));
        assertThat(kept.bvh(frame(1, 0, 0, triangle))).isSameAs(bvh);
        assertThat(kept.bvh(frame(2, 0, 0, triangle()))).isNotSameAs(bvh);
    }

    private static Triangle triangle() {
        return new Triangle(new Vector3f(2, 0, 0), new Vector3f(3, 0, 0), new Vector3f(2, 1, 0), RED, Material.DEFAULT);
    }
}
