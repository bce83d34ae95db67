package gfx.tick1;

public class Sphere {

    // Sphere coefficients
    private final double SPHERE_KD = 0.8;
    private final double SPHERE_KS = 0.8;
    private final double SPHERE_ALPHA = 10;

    // The world-space position of the sphere
    private Vector3 position;

    // The radius of the sphere in world units
    private double radius;

    // The colour of the sphere
    private Vector3 colour;

    public Sphere(Vector3 position, double radius, Vector3 colour) {
        this.position = position;
        this.radius = radius;
        this.colour = colour;
    }

    /*
     * Calculate intersection of the sphere with the ray. If the ray starts inside the sphere,
     * intersection with the surface is also found.
     */
    public RaycastHit intersectionWith(Ray ray) {

        Vector3 O = ray.getOrigin();
        Vector3 D = ray.getDirection();
        Vector3 C = position;
        double r = radius;

        // Determine quadratic equation constants
        double a = D.dot(D);
        double b = 2 * D.dot(O.subtract(C));
        double c = (O.subtract(C).dot(O.subtract(C)) - Math.pow(r, 2));

        // Determine if ray and sphere intersect
        double discriminant = b * b - 4 * a * c;
        if (discriminant < 0) {
            return new RaycastHit();
        }

        // The two solutions; s1 <= s2 because a > 0
        double s1 = (-b - Math.sqrt(discriminant)) / (2 * a);
        double s2 = (-b + Math.sqrt(discriminant)) / (2 * a);

        // The closest solution in front of the ray origin
        double s = s1 > 0 ? s1 : s2;
        if (s <= 0) {
            return new RaycastHit();
        }

        // Work out point of intersection and return the hit
        Vector3 point = ray.evaluateAt(s);
        Vector3 normal = this.getNormalAt(point);
        return new RaycastHit(this, s, point, normal);
    }

    // Get normal to surface at position
    public Vector3 getNormalAt(Vector3 position) {
        return position.subtract(this.position).normalised();
    }

    public Vector3 getColour() {
        return colour;
    }

    public double getPhong_kD() {
        return SPHERE_KD;
    }

    public double getPhong_kS() {
        return SPHERE_KS;
    }

    public double getPhong_n() {
        return SPHERE_ALPHA;
    }
}
