package gfx.tick1.engine.scene;

import gfx.tick1.engine.math.Vector3;

/** Where a ray met a sphere; the empty hit (no sphere, distance +infinity) stands for a miss. */
public final class RaycastHit {

    private final Sphere objectHit;
    private final double distance;
    private final Vector3 location;
    private final Vector3 normal;

    /** A miss: +infinity is farther than any real hit, so "strictly closer" comparisons just work. */
    public RaycastHit() {
        this(null, Double.POSITIVE_INFINITY, null, null);
    }

    public RaycastHit(Sphere objectHit, double distance, Vector3 location, Vector3 normal) {
        this.objectHit = objectHit;
        this.distance = distance;
        this.location = location;
        this.normal = normal;
    }

    public Sphere getObjectHit() {
        return objectHit;
    }

    public double getDistance() {
        return distance;
    }

    public Vector3 getLocation() {
        return location;
    }

    public Vector3 getNormal() {
        return normal;
    }

    public boolean isHit() {
        return objectHit != null;
    }
}
