package gfx.tick1.scene;

import gfx.tick1.math.Ray;
import gfx.tick1.math.Vector3;

/** A sphere |P - C|^2 = r^2 with a flat diffuse colour and the tick's fixed Phong coefficients. */
public final class Sphere {

    // Tick 1 gives every sphere the same material (handout section 5: "k_d and k_s have been set
    // to constants"); the values are the starter code's.
    private static final double PHONG_KD = 0.8;
    private static final double PHONG_KS = 0.8;
    private static final double PHONG_N = 10;

    private final Vector3 position;
    private final double radius;
    private final Vector3 colour;

    public Sphere(Vector3 position, double radius, Vector3 colour) {
        this.position = position;
        this.radius = radius;
        this.colour = colour;
    }

    /**
     * The nearest intersection in front of the ray's origin, or an empty hit.
     *
     * <p>Substituting the ray P(s) = O + s D into the sphere gives a s^2 + b s + c = 0 with
     * a = D.D, b = 2 D.(O - C), c = (O - C).(O - C) - r^2 (handout section 4). The handout's
     * recipe compares s1 &lt; s2, which says nothing when one root is behind the origin (the
     * camera inside the sphere) or the roots are equal (a tangent ray); we take the smallest
     * root with s &gt; 0 in every case, as the reference spec requires.
     */
    public RaycastHit intersectionWith(Ray ray) {
        Vector3 O = ray.getOrigin();
        Vector3 D = ray.getDirection();
        Vector3 C = position;
        double r = radius;

        double a = D.dot(D);
        double b = 2 * D.dot(O.subtract(C));
        double c = O.subtract(C).dot(O.subtract(C)) - Math.pow(r, 2);

        double discriminant = b * b - 4 * a * c;
        if (discriminant < 0) {
            return new RaycastHit();
        }
        double root = Math.sqrt(discriminant);
        double s1 = (-b - root) / (2 * a);
        double s2 = (-b + root) / (2 * a);

        // s1 <= s2 because a > 0 and root >= 0.
        double s = s1 > 0 ? s1 : s2;
        if (!(s > 0)) {
            return new RaycastHit();
        }
        Vector3 point = ray.evaluateAt(s);
        Vector3 normal = getNormalAt(point);
        return new RaycastHit(this, s, point, normal);
    }

    /** The outward unit normal at a point on the surface: normalise(P - C). */
    public Vector3 getNormalAt(Vector3 point) {
        return point.subtract(position).normalised();
    }

    public Vector3 getPosition() {
        return position;
    }

    public double getRadius() {
        return radius;
    }

    public Vector3 getColour() {
        return colour;
    }

    public double getPhong_kD() {
        return PHONG_KD;
    }

    public double getPhong_kS() {
        return PHONG_KS;
    }

    public double getPhong_n() {
        return PHONG_N;
    }

    @Override
    public String toString() {
        return "Sphere(centre " + position + ", radius " + radius + ", colour " + colour + ")";
    }
}
