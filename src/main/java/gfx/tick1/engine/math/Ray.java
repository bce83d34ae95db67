package gfx.tick1.engine.math;

/** The ray P(s) = O + s D of the handout's section 4. D is a unit vector for camera rays. */
public final class Ray {

    private final Vector3 origin;
    private final Vector3 direction;

    public Ray(Vector3 origin, Vector3 direction) {
        this.origin = origin;
        this.direction = direction;
    }

    public Vector3 getOrigin() {
        return origin;
    }

    public Vector3 getDirection() {
        return direction;
    }

    /** P(s) = O + s D. */
    public Vector3 evaluateAt(double distance) {
        return origin.add(direction.scale(distance));
    }

    @Override
    public String toString() {
        return "Ray(" + origin + " + s " + direction + ")";
    }
}
