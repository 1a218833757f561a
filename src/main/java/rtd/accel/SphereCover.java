package rtd.accel;

import rtd.geometry.Sphere;
import rtd.render.HitBuffer;

/**
 * A square of parallel rays inside the outline of a sphere, found by a {@link BeamTracer}'s
 * walk before any ray is made: the sphere is the only object the beam reaches in its leaf, and
 * every ray of the square surely hits it ({@link SphereOutline#everyRayHitsBefore}). Unless the
 * walk meets another object in reach before the sphere's hits, every ray's answer is that
 * sphere, and none need be traced: in a flat picture, most squares inside a large sphere. Not
 * in the paper.
 *
 * <p>Looked for only where it can pay ({@link #reset}): when only the object is asked for, the
 * rays are parallel, and the tree's largest sphere is wider than the square. Not looked for where
 * it cannot (a million small spheres), the check drops out of the code the JIT compiles: with
 * it, their first render took 0.4 s longer.
 */
final class SphereCover {

    private final Bvh bvh;
    private final Beam beam;
    private final MiddleRay middle;
    /** The largest squared radius of the tree's spheres. */
    private final float largestSphereSquared;
    /** Whether a sphere could cover this square at all. */
    private boolean coverable;
    /** The sphere found (its place among the leaves' objects), or −1. */
    private int sphere = -1;
    /**
     * The sphere's leaf, the beam's entry into its objects' boxes and their growth: where the
     * rays are traced after all if another object is in reach.
     */
    private int leaf;
    private float reach;
    private float grow;
    /** A t beyond which no box can hold a hit nearer than the sphere's, for any ray of the square. */
    private float skipBeyond;

    SphereCover(Bvh bvh, Beam beam, MiddleRay middle) {
        this.bvh = bvh;
        this.beam = beam;
        this.middle = middle;
        this.largestSphereSquared = bvh.leaves.largestSphereSquared();
    }

    /**
     * Starts a new square, with no sphere found: one could cover it only if only the object is
     * asked for, the rays are parallel, and the tree's largest sphere is wider than the beam.
     */
    void reset(HitBuffer out) {
        sphere = -1;
        coverable = !out.hitPointsRead() && middle.parallel && largestSphereSquared
                > middle.half[0] * middle.half[0] + middle.half[1] * middle.half[1] + middle.half[2] * middle.half[2];
    }

    /** Whether a sphere is still worth looking for: the square could be covered, and none is found yet. */
    boolean worthLooking() {
        return sphere < 0 && coverable;
    }

    /**
     * Whether the beam reaches only one object of the leaf, within the walk's bound
     * {@code farthestSkip}, and that object is a sphere every ray of the square hits; if so, it
     * is remembered with its leaf and the beam's entry into the leaf's objects' boxes,
     * {@code reach}, and {@link #skipBeyond} says where the walk may stop looking.
     */
    boolean covers(int leaf, float grow, float within, float reach, float farthestSkip) {
        int only = onlyObjectInReach(leaf, grow, within, farthestSkip);
        if (only < 0 || !(bvh.objects.get(bvh.leaves.fileOrder[only]) instanceof Sphere found)) {
            return false;
        }
        double before = SphereOutline.everyRayHitsBefore(found, beam.lowest, beam.highest, beam.dx, beam.dy, beam.dz);
        if (!(before >= 0)) {
            return false;
        }
        double origins = Math.sqrt(square(Math.abs(middle.centre[0]) + middle.half[0])
                + square(Math.abs(middle.centre[1]) + middle.half[1]) + square(Math.abs(middle.centre[2]) + middle.half[2]));
        sphere = only;
        this.leaf = leaf;
        this.reach = reach;
        this.grow = grow;
        // a ray's skip distance for a hit there (NearestHit.skipFor), generously: boxes beyond cannot hold a nearer hit
        skipBeyond = (float) (before * (1 + 1e-4) + 1e-4 * origins / middle.shortest);
        return true;
    }

    /** Whether a sphere covers the square. */
    boolean found() {
        return sphere >= 0;
    }

    /** The covering sphere's place in the file, the answer of every ray of the square. */
    int sphereInFile() {
        return bvh.leaves.fileOrder[sphere];
    }

    /** Forgets the sphere: another object is in reach after all, and the rays are traced. */
    void forget() {
        sphere = -1;
    }

    float skipBeyond() {
        return skipBeyond;
    }

    /** The sphere's leaf, where the rays are to be traced after all if another object is in reach. */
    int leaf() {
        return leaf;
    }

    /** The beam's entry into the boxes of the objects of the sphere's leaf. */
    float reach() {
        return reach;
    }

    float grow() {
        return grow;
    }

    /** The one object of the leaf whose box the beam reaches before {@code farthestSkip}, or −1 if none or several do. */
    private int onlyObjectInReach(int leaf, float grow, float within, float farthestSkip) {
        int first = bvh.nodes[2 * leaf];
        int end = first + bvh.nodes[2 * leaf + 1];
        int only = -1;
        for (int i = first; i < end; i++) {
            // the walk's test of an entry (BeamTracer.worthVisiting, NearestHit.worthVisiting)
            if (middle.objectEntry(i, grow, within) <= FastMath.min(farthestSkip, Float.MAX_VALUE)) {
                if (only >= 0) {
                    return -1;
                }
                only = i;
            }
        }
        return only;
    }

    private static double square(double x) {
        return x * x;
    }
}
