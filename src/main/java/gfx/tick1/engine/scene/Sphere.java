package gfx.tick1.engine.scene;

import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;

public class Sphere {

    // Every sphere of the tick has the same Phong coefficients
    private final double SPHERE_KD = 0.8;
    private final double SPHERE_KS = 0.8;
    private final double SPHERE_N = 10;

    // Diffuse colour C_diff, red, green and blue from 0 to 1
    private Vector3 colour;

    // Centre C, in the scene's coordinates
    private Vector3 position;

    // Radius r, in the same units as the centre
    private double radius;

    private double phong_kD, phong_kS, phong_n;

    public Sphere(Vector3 position, double radius, Vector3 colour) {
        this.position = position;
        this.radius = radius;
        this.colour = colour;

        phong_kD = SPHERE_KD;
        phong_kS = SPHERE_KS;
        phong_n = SPHERE_N;
    }

    /*
     * The nearest point where the ray meets the sphere in front of its origin, found by solving
     * a s^2 + b s + c = 0 for the ray P(s) = O + s D; an empty RaycastHit when there is none.
     */
    public RaycastHit intersectionWith(Ray ray) {

        Vector3 O = ray.getOrigin();
        Vector3 D = ray.getDirection();
        Vector3 C = position;
        double r = radius;

        // Determine quadratic equation constants
        double a = D.dot(D);
        double b = 2 * D.dot(O.subtract(C));
        double c = (O.subtract(C)).dot(O.subtract(C)) - Math.pow(r, 2);

        // A negative discriminant means the ray misses the sphere
        double discriminant = b * b - 4 * a * c;
        if (discriminant < 0) {
            return new RaycastHit();
        }

        // The two roots, s1 <= s2 since a > 0; the nearer one in front of the origin is the hit
        double s1 = (-b - Math.sqrt(discriminant)) / (2 * a);
        double s2 = (-b + Math.sqrt(discriminant)) / (2 * a);
        double s = s1 > 0 ? s1 : s2;

        // The hit: this sphere, the distance along the ray, the point and the normal there
        if (s > 0) {
            Vector3 point = ray.evaluateAt(s);
            Vector3 normal = this.getNormalAt(point);
            return new RaycastHit(this, s, point, normal);
        }

        // Currently returning empty RaycastHit for no intersection
        return new RaycastHit();
    }

    // The outward unit normal at a point on the surface: normalise(P - C)
    public Vector3 getNormalAt(Vector3 position) {
        return position.subtract(this.position).normalised();
    }

    public Vector3 getColour() { return colour; }
    public double getPhong_kD() { return phong_kD; }
    public double getPhong_kS() { return phong_kS; }
    public double getPhong_n() { return phong_n; }
}
