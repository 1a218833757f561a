package rtd.io;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.camera.OrthographicCamera;
import rtd.camera.PerspectiveCamera;
import rtd.geometry.Box;
import rtd.geometry.Material;
import rtd.geometry.Plane;
import rtd.geometry.Sphere;
import rtd.geometry.Triangle;
import rtd.image.Color;
import rtd.image.Rgb;
import rtd.math.Vector3f;
import rtd.scene.Light;
import rtd.scene.Scene;

/** The statements of Part II read into the objects they name, with every field as written. */
@DisplayName("The statements beyond the paper")
class NewStatementsTest {

    private static final String CAMERA = "orthographic_camera:(0|0|20):(0|0|-1):(50)\n";
    private static final Color RED = new Color(255, 0, 0);

    private static Scene read(String text) throws SceneException {
        return SceneIO.parseScene("scene.txt", text);
    }

    @Test
    void aPerspectiveCameraHasItsPositionDirectionAndFieldOfView() throws SceneException {
        Scene scene = read("perspective_camera:(1|2|3):(0|-0.5|-1):(60)");
        PerspectiveCamera camera = (PerspectiveCamera) scene.camera();
        assertThat(camera.position()).isEqualTo(new Vector3f(1, 2, 3));
        assertThat(camera.direction()).isEqualTo(new Vector3f(0, -0.5f, -1));
        assertThat(camera.fieldOfView()).isEqualTo(60f);
    }

    @Test
    void aPerspectiveCameraMayLookStraightDownAsTheOrthographicOneMay() throws SceneException {
        assertThat(read("perspective_camera:(0|10|0):(0|-1|0):(90)").camera()).isInstanceOf(PerspectiveCamera.class);
    }

    @Test
    void lightsAreReadInFileOrderWithTheirIntensityAsAFractionOf255() throws SceneException {
        Scene scene = read(CAMERA + "light:(-10|10|-10):(255|255|255)\nsphere:(0|0|0):(1):(255|0|0)\nlight:(1|2|3):(51|0|255)");
        assertThat(scene.lights()).containsExactly(new Light(new Vector3f(-10, 10, -10), new Rgb(1, 1, 1)),
                new Light(new Vector3f(1, 2, 3), new Rgb(0.2f, 0, 1)));
        assertThat(read(CAMERA).lights()).as("a scene without lights is flat").isEmpty();
    }

    @Test
    void aSphereWithoutMaterialHasTheDefaultFinish() throws SceneException {
        Scene scene = read(CAMERA + "sphere:(1|2|3):(4):(255|0|0)");
        assertThat(scene.objects()).containsExactly(new Sphere(new Vector3f(1, 2, 3), 4, RED, Material.DEFAULT));
    }

    @Test
    void aPlaneHasItsPointNormalColourAndFinish() throws SceneException {
        Scene scene = read(CAMERA + "plane:(0|-1|0):(0|2|0):(255|0|0)");
        assertThat(scene.objects()).containsExactly(
                new Plane(new Vector3f(0, -1, 0), new Vector3f(0, 2, 0), RED, Material.DEFAULT));
    }

    @Test
    void aTriangleHasItsThreeCornersInOrder() throws SceneException {
        Triangle triangle = (Triangle) read(CAMERA + "triangle:(0|0|0):(1|0|0):(0|2|0):(255|0|0)").objects().get(0);
        assertThat(triangle.corner(0)).isEqualTo(new Vector3f(0, 0, 0));
        assertThat(triangle.corner(1)).isEqualTo(new Vector3f(1, 0, 0));
        assertThat(triangle.corner(2)).isEqualTo(new Vector3f(0, 2, 0));
        assertThat(triangle.planeNormal()).isEqualTo(new Vector3f(0, 0, 2));
        assertThat(triangle.isSmooth()).isFalse();
        assertThat(triangle.color()).isEqualTo(RED);
        assertThat(triangle.material()).isEqualTo(Material.DEFAULT);
    }

    @Test
    void aBoxTakesItsCornersInAnyOrder() throws SceneException {
        Scene scene = read(CAMERA + "box:(1|-2|3):(-1|2|-3):(255|0|0)");
        assertThat(scene.objects()).containsExactly(
                new Box(new Vector3f(-1, -2, -3), new Vector3f(1, 2, 3), RED, Material.DEFAULT));
    }

    @Test
    void aMaterialDefinedBeforeItsUseIsAttached() throws SceneException {
        Scene scene = read(CAMERA + "material:(glass):(transparency=0.9|ior=1.5)\nsphere:(0|0|0):(1):(255|0|0):(glass)");
        assertThat(scene.objects().get(0).material()).isEqualTo(new Material(0.1f, 0.9f, 0.9f, 200, 0, 0.9f, 1.5f));
    }

    @Test
    void aMaterialDefinedAfterItsUseIsAttachedToo() throws SceneException {
        Scene scene = read(CAMERA + "box:(0|0|0):(1|1|1):(255|0|0):(mirror)\nmaterial:(mirror):(reflective=1|specular=0)");
        assertThat(scene.objects().get(0).material()).isEqualTo(new Material(0.1f, 0.9f, 0f, 200, 1, 0, 1));
    }

    @Test
    void aMaterialWithEveryKeyTakesThemAllAndOneWithNoneIsTheDefault() throws SceneException {
        Scene scene = read(CAMERA + "material:(all):(ambient=1|diffuse=2|specular=3|shininess=4|reflective=5|transparency=6|ior=7)\n"
                + "material:(plain-1):()\nplane:(0|0|0):(0|1|0):(0|0|0):(all)\nplane:(0|0|0):(0|1|0):(0|0|0):( plain-1 )");
        assertThat(scene.objects().get(0).material()).isEqualTo(new Material(1, 2, 3, 4, 5, 6, 7));
        assertThat(scene.objects().get(1).material()).isEqualTo(Material.DEFAULT);
    }

    @Test
    void objectsWithAndWithoutMaterialKeepTheOrderOfTheFile() throws SceneException {
        Scene scene = read(CAMERA + "sphere:(1|0|0):(1):(0|0|0)\nsphere:(2|0|0):(1):(0|0|0):(m)\nsphere:(3|0|0):(1):(0|0|0)\n"
                + "material:(m):(diffuse=0.5)\nsphere:(4|0|0):(1):(0|0|0):(m)\nsphere:(5|0|0):(1):(0|0|0)");
        assertThat(scene.objects()).extracting(o -> ((Sphere) o).center().x()).containsExactly(1f, 2f, 3f, 4f, 5f);
        assertThat(scene.objects()).extracting(o -> o.material().diffuse()).containsExactly(0.9f, 0.5f, 0.9f, 0.5f, 0.9f);
    }

    @Test
    void blanksAroundNamesKeysAndValuesAreFine() throws SceneException {
        Scene scene = read(CAMERA + "material : ( glass ) : ( ior = 1.5 | transparency\t=\t1 )\n"
                + "sphere:(0|0|0):(1):(255|0|0) : ( glass ) // see-through");
        assertThat(scene.objects().get(0).material().ior()).isEqualTo(1.5f);
    }

    @Test
    void aStatementMayHoldAnyNumberOfNumbers() throws SceneException {
        // 12 numbers and a colour: more than the reader of the paper's three statements held
        Scene scene = read(CAMERA + "triangle:(0|0|0):(1|0|0):(0|1|0):(1|2|3)\n".repeat(3));
        assertThat(scene.objects()).hasSize(3);
    }

    @Test
    void theOrthographicCameraIsStillTheOneOfThePaper() throws SceneException {
        OrthographicCamera camera = (OrthographicCamera) read(CAMERA).camera();
        assertThat(camera.zoom()).isEqualTo(50f);
    }
}
