package rtd.geometry;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import rtd.image.Color;
import rtd.math.Matrix4;
import rtd.math.Ray;
import rtd.math.Vector3f;

@DisplayName("A transformed shape (The Ray Tracer Challenge, chapters 4 and 14)")
class TransformedTest {

    private static final Sphere UNIT = new Sphere(new Vector3f(0, 0, 0), 1, Color.BLACK);

    private static Ray ray(float ox, float oy, float oz, float dx, float dy, float dz) {
        return new Ray(new Vector3f(ox, oy, oz), new Vector3f(dx, dy, dz));
    }

    @Test
    void aRayHitsAStretchedSphereWhereTheEllipsoidIs() {
        // the unit sphere scaled by 2 in x: the ellipsoid reaches x = 2; a ray from x = 10 along -x hits at t = 8
        Transformed ellipsoid = new Transformed(UNIT, Matrix4.scale(2, 1, 1));
        Intersection hit = ellipsoid.intersect(ray(10, 0, 0, -1, 0, 0));
        assertThat(hit.t()).isEqualTo(8f);
        assertThat(hit.contactCoord()).isEqualTo(new Vector3f(2, 0, 0));
    }

    @Test
    void theRayInTheShapesSpaceKeepsTheSameT() {
        // M = translate 0|0|5: M⁻¹O = (0|0|5), M⁻¹R = R; the sphere's own test hits at t = 4, as in the world
        Transformed moved = new Transformed(UNIT, Matrix4.translate(0, 0, -5));
        Ray local = moved.objectRay(ray(0, 0, 0, 0, 0, -1));
        assertThat(local.origin()).isEqualTo(new Vector3f(0, 0, 5));
        assertThat(moved.intersect(ray(0, 0, 0, 0, 0, -1)).t()).isEqualTo(4f);
    }

    @Test
    void aScaledSpheresNormalTurnsByTheInverseTranspose() {
        // scale 1|0.5|1 squashes the sphere; at the world point (0|0.35355|-0.70711), which is (0|0.70711|-0.70711) in
        // the sphere's space, the sphere's normal is (0|0.70711|-0.70711); (M⁻¹)ᵀ = diag(1, 2, 1) makes it
        // (0|1.41421|-0.70711), of length 1.58114: normalised (0|0.89443|-0.44721), steeper than the sphere's
        Transformed squashed = new Transformed(UNIT, Matrix4.scale(1, 0.5, 1));
        float h = (float) Math.sqrt(0.5);
        Vector3f n = squashed.normalAt(new Vector3f(0, h * 0.5f, -h));
        assertThat(n.x()).isCloseTo(0f, within(1e-6f));
        assertThat(n.y()).isCloseTo(0.89443f, within(1e-5f));
        assertThat(n.z()).isCloseTo(-0.44721f, within(1e-5f));
    }

    @Test
    void aTranslatedSpheresNormalIsTheSpheresNormalMoved() {
        Transformed moved = new Transformed(UNIT, Matrix4.translate(0, 1, 0));
        assertThat(moved.normalAt(new Vector3f(0, 1.70711f, -0.70711f)).y()).isCloseTo(0.70711f, within(1e-5f));
    }

    @Test
    void aRotatedBoxsBoxHoldsItsTurnedCorners() {
        // the cube from -1 to 1 turned 45° about y: its corners reach x = ±√2 = ±1.41421
        Box cube = Box.between(new Vector3f(-1, -1, -1), new Vector3f(1, 1, 1), Color.BLACK, Material.DEFAULT);
        BoundingBox box = new Transformed(cube, Matrix4.rotateY(45)).bounds();
        assertThat(box.max().x()).isGreaterThan(1.41421f).isLessThan(1.4143f);
        assertThat(box.min().z()).isLessThan(-1.41421f).isGreaterThan(-1.4143f);
        assertThat(box.max().y()).isGreaterThan(1f).isLessThan(1.0001f);
    }

    @Test
    void aTurnedBoxIsHitOnItsEdgeWhereTheCornerNowPoints() {
        // turned 45° about y, the cube's edge at x = z = 1 points along +x to x = √2: a ray along -x hits at 10 - √2
        Box cube = Box.between(new Vector3f(-1, -1, -1), new Vector3f(1, 1, 1), Color.BLACK, Material.DEFAULT);
        Intersection hit = new Transformed(cube, Matrix4.rotateY(45)).intersect(ray(10, 0, 0, -1, 0, 0));
        assertThat(hit.t()).isCloseTo(10 - 1.41421f, within(1e-5f));
    }

    @Test
    void aTransformedPlaneStaysUnbounded() {
        Plane floor = new Plane(new Vector3f(0, 0, 0), new Vector3f(0, 1, 0), Color.BLACK, Material.DEFAULT);
        Transformed tilted = new Transformed(floor, Matrix4.rotateZ(30));
        assertThat(tilted.bounds().isBounded()).isFalse();
    }

    @Test
    void aRotatedPlanesNormalTurnsWithIt() {
        // the floor's normal (0|1|0) turned 90° about z points along -x
        Plane floor = new Plane(new Vector3f(0, 0, 0), new Vector3f(0, 1, 0), Color.BLACK, Material.DEFAULT);
        Vector3f n = new Transformed(floor, Matrix4.rotateZ(90)).normalAt(new Vector3f(0, 3, 0));
        assertThat(n).isEqualTo(new Vector3f(-1, 0, 0));
    }

    @Test
    void aTransformedMeshTriangleIsHitWhereItWasMoved() {
        // the triangle (0|0|0), (1|0|0), (0|1|0) moved by 0|0|-3 and scaled by 2 first: hit at (0.5|0.5|-3), t = 3
        Triangle t = new Triangle(new Vector3f(0, 0, 0), new Vector3f(1, 0, 0), new Vector3f(0, 1, 0), Color.BLACK,
                Material.DEFAULT);
        Transformed placed = new Transformed(t, Matrix4.scale(2, 2, 2).then(Matrix4.translate(0, 0, -3)));
        Intersection hit = placed.intersect(ray(0.5f, 0.5f, 0, 0, 0, -1));
        assertThat(hit.t()).isEqualTo(3f);
        assertThat(placed.intersect(ray(1.5f, 0.9f, 0, 0, 0, -1)).happened()).isFalse(); // x + y = 2.4 > 2
    }

    @Test
    void itIsNeverTakenForItsShape() {
        Transformed ellipsoid = new Transformed(UNIT, Matrix4.scale(2, 1, 1));
        assertThat((IGeometry) ellipsoid).isNotInstanceOf(Sphere.class);
        assertThat(ellipsoid.kind()).isEqualTo("sphere");
    }
}
