package rtd.accel;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import rtd.geometry.IGeometry;
import rtd.geometry.Sphere;
import rtd.image.Color;
import rtd.math.Ray;
import rtd.math.Vector3f;

/**
 * Rays that graze what a grid seen from a point X must hold, for the tests of the grids seen from
 * a light: a point Q just inside the outline of a box as X sees it, with
 * the side it lies on; and the vector arithmetic, in double, to aim rays past it.
 *
 * @param q    Q less X: just inside the corner of the box that shows farthest towards the side
 * @param side a unit vector at right angles to the direction of the box's middle, chosen at random
 */
record Grazing(double[] q, double[] side) {

    /** A point just inside the outline of {@code box} seen from {@code x}, on a random side, 1e-6 to 1e-2 in. */
    static Grazing of(float[] box, double[] x, Random random) {
        double[] boxMiddle = {(box[0] + box[3]) / 2 - x[0], (box[1] + box[4]) / 2 - x[1], (box[2] + box[5]) / 2 - x[2]};
        double[] toMiddle = unit(boxMiddle);
        double[] side = unit(across(new double[] {random.nextGaussian(), random.nextGaussian(), random.nextGaussian()},
                toMiddle));
        double[] q = null;
        for (int k = 0; k < 8; k++) {
            double[] w = {box[(k & 1) * 3] - x[0], box[1 + (k >> 1 & 1) * 3] - x[1], box[2 + (k >> 2 & 1) * 3] - x[2]};
            if (q == null || dot(w, side) / dot(w, toMiddle) > dot(q, side) / dot(q, toMiddle)) {
                q = w;
            }
        }
        double inside = Math.pow(10, -6 + 4 * random.nextDouble());
        for (int k = 0; k < 3; k++) {
            q[k] += inside * Math.signum(boxMiddle[k] - q[k]);
        }
        return new Grazing(q, side);
    }

    /** A unit vector at right angles to Q, away from the side: a line through X moved this way reaches Q from outside the outline. */
    double[] awayFromSide() {
        return unit(across(new double[] {-side[0], -side[1], -side[2]}, unit(q)));
    }

    static Vector3f point(double x, double y, double z) {
        return new Vector3f((float) x, (float) y, (float) z);
    }

    static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    static double[] unit(double[] a) {
        double length = Math.sqrt(dot(a, a));
        return new double[] {a[0] / length, a[1] / length, a[2] / length};
    }

    /** The part of {@code a} at right angles to the unit vector {@code axis}. */
    static double[] across(double[] a, double[] axis) {
        double along = dot(a, axis);
        return new double[] {a[0] - along * axis[0], a[1] - along * axis[1], a[2] - along * axis[2]};
    }

    /**
     * 400 spheres of radius 0.0005 to 0.0025 within 8 units of (0|40|0), drawn from {@code random}: so small that the
     * float test reports hits beside them, which a grid or a tree must find as the loop does. A list to add to.
     */
    static List<IGeometry> tinySpheres(Random random) {
        List<IGeometry> spheres = new ArrayList<>();
        for (int i = 0; i < 400; i++) {
            Vector3f centre = new Vector3f((random.nextFloat() * 2 - 1) * 8, 40 + (random.nextFloat() * 2 - 1) * 8,
                    (random.nextFloat() * 2 - 1) * 8);
            spheres.add(new Sphere(centre, 0.0005f + random.nextFloat() * 0.002f, new Color(200, 100, 50)));
        }
        return spheres;
    }

    /** Whether the exact line of the ray passes the sphere by. */
    static boolean missesExactly(Ray ray, Sphere sphere) {
        double[] o = {ray.origin().x(), ray.origin().y(), ray.origin().z()};
        double[] d = {ray.direction().x(), ray.direction().y(), ray.direction().z()};
        double[] c = {sphere.center().x(), sphere.center().y(), sphere.center().z()};
        double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        double t = ((c[0] - o[0]) * d[0] + (c[1] - o[1]) * d[1] + (c[2] - o[2]) * d[2]) / dd;
        double gap = 0;
        for (int k = 0; k < 3; k++) {
            double offset = o[k] + t * d[k] - c[k];
            gap += offset * offset;
        }
        return Math.sqrt(gap) > sphere.radius();
    }
}
