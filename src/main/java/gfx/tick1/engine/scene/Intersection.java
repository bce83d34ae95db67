package gfx.tick1.engine.scene;

import gfx.tick1.engine.math.Ray;

/**
 * How a ray is intersected with a sphere. {@link #ROBUST} is the renderer's default;
 * {@link #HANDOUT} is the student handout's formula as it stands, kept so that tests and the
 * benchmark can show where it fails. On ordinary scenes the two give the same image bit for bit.
 */
public enum Intersection {

    /** {@link RobustIntersection}: the handout's answer where that is accurate, a stable one elsewhere. */
    ROBUST {
        @Override
        public RaycastHit find(Sphere sphere, Ray ray) {
            return RobustIntersection.intersect(sphere, ray);
        }
    },

    /** {@link RobustIntersection#stable}: the stable formula everywhere, for measurements only. */
    STABLE {
        @Override
        public RaycastHit find(Sphere sphere, Ray ray) {
            return RobustIntersection.stable(sphere, ray);
        }
    },

    /** {@link Sphere#intersectionWith}: s = (-b +- sqrt(b^2 - 4ac)) / 2a in plain doubles. */
    HANDOUT {
        @Override
        public RaycastHit find(Sphere sphere, Ray ray) {
            return sphere.intersectionWith(ray);
        }
    };

    /** The renderer's choice when none is given. */
    public static final Intersection DEFAULT = ROBUST;

    /** The nearest hit of the ray on the sphere with s &gt; 0, or the empty hit. */
    public abstract RaycastHit find(Sphere sphere, Ray ray);
}
