package gfx.tick1.command.shared.grader.harness;

import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;

/**
 * The starter kit's classes and the student's two, reached by reflection in the JVM that runs the
 * student's code: the harness may not link against them, as they are compiled for each student.
 * {@code Renderer.illuminate} is private in the starter code, so it is opened here; a Renderer
 * whose illuminate has another signature has none ({@link #hasIlluminate}).
 */
final class StarterApi {

    private final Class<?> vector3, ray, sphere, scene, pointLight, renderer, camera;
    private final Constructor<?> newVector3, newRay, newSphere, newScene, newPointLight, newRenderer, newCamera;
    private final Method intersectionWith, illuminate, castRay, toRgb, setAmbientLight, setPointLight;
    private final Method getObjectHit, getDistance, getLocation, getNormal, findClosestIntersection;
    /** The starter Sphere's fields of k_d, k_s and n, opened; null when the student's Sphere lacks one. */
    private final Field[] phong;
    private final Field x, y, z;

    StarterApi(ClassLoader student) throws ReflectiveOperationException {
        vector3 = student.loadClass("gfx.tick1.Vector3");
        ray = student.loadClass("gfx.tick1.Ray");
        sphere = student.loadClass("gfx.tick1.Sphere");
        scene = student.loadClass("gfx.tick1.Scene");
        pointLight = student.loadClass("gfx.tick1.PointLight");
        renderer = student.loadClass("gfx.tick1.Renderer");
        camera = student.loadClass("gfx.tick1.Camera");
        Class<?> hit = student.loadClass("gfx.tick1.RaycastHit");
        newVector3 = vector3.getConstructor(double.class, double.class, double.class);
        newRay = ray.getConstructor(vector3, vector3);
        newSphere = sphere.getConstructor(vector3, double.class, vector3);
        newScene = scene.getConstructor();
        newPointLight = pointLight.getConstructor(vector3, vector3, double.class);
        newRenderer = renderer.getConstructor(int.class, int.class);
        newCamera = camera.getConstructor(int.class, int.class);
        intersectionWith = sphere.getMethod("intersectionWith", ray);
        illuminate = findIlluminate();
        castRay = camera.getMethod("castRay", int.class, int.class);
        toRgb = vector3.getMethod("toRGB");
        setAmbientLight = scene.getMethod("setAmbientLight", vector3);
        setPointLight = scene.getMethod("setPointLight", pointLight);
        findClosestIntersection = scene.getMethod("findClosestIntersection", ray);
        getObjectHit = hit.getMethod("getObjectHit");
        getDistance = hit.getMethod("getDistance");
        getLocation = hit.getMethod("getLocation");
        getNormal = hit.getMethod("getNormal");
        phong = phongFields();
        x = vector3.getField("x");
        y = vector3.getField("y");
        z = vector3.getField("z");
    }

    private Method findIlluminate() {
        try {
            Method method = renderer.getDeclaredMethod("illuminate", scene, sphere, vector3, vector3);
            method.setAccessible(true);
            return method.getReturnType() == vector3 ? method : null;
        } catch (NoSuchMethodException | RuntimeException e) {
            return null;
        }
    }

    private Field[] phongFields() {
        try {
            Field[] fields = {sphere.getDeclaredField("phong_kD"), sphere.getDeclaredField("phong_kS"),
                sphere.getDeclaredField("phong_n")};
            for (Field field : fields) {
                if (field.getType() != double.class || Modifier.isFinal(field.getModifiers())
                        || Modifier.isStatic(field.getModifiers())) {
                    return null;
                }
                field.setAccessible(true);
            }
            return fields;
        } catch (NoSuchFieldException | RuntimeException e) {
            return null;
        }
    }

    /** Whether a sphere's k_d, k_s and n can be set: the student's Sphere keeps the starter's fields. */
    boolean hasPhongFields() {
        return phong != null;
    }

    /** Sets k_d, k_s and n of {@code aSphere} through the starter's fields (see {@link #hasPhongFields}). */
    void setPhong(Object aSphere, double kD, double kS, double n) throws ReflectiveOperationException {
        phong[0].setDouble(aSphere, kD);
        phong[1].setDouble(aSphere, kS);
        phong[2].setDouble(aSphere, n);
    }

    boolean hasIlluminate() {
        return illuminate != null;
    }

    Object vector(double[] xyz) throws ReflectiveOperationException {
        return construct(newVector3, xyz[0], xyz[1], xyz[2]);
    }

    Object ray(double[] origin, double[] direction) throws ReflectiveOperationException {
        return construct(newRay, vector(origin), vector(direction));
    }

    Object sphere(double[] centre, double radius, double[] colour) throws ReflectiveOperationException {
        return construct(newSphere, vector(centre), radius, vector(colour));
    }

    /** A scene of the starter code with this ambient light and point light, and no spheres. */
    Object scene(double[] ambient, double[] lightPosition, double[] lightColour, double intensity)
            throws ReflectiveOperationException {
        Object made = construct(newScene);
        call(setAmbientLight, made, vector(ambient));
        call(setPointLight, made, construct(newPointLight, vector(lightPosition), vector(lightColour), intensity));
        return made;
    }

    Object renderer(int width, int height) throws ReflectiveOperationException {
        return construct(newRenderer, width, height);
    }

    Object camera(int width, int height) throws ReflectiveOperationException {
        return construct(newCamera, width, height);
    }

    Object castRay(Object aCamera, int px, int py) throws ReflectiveOperationException {
        return call(castRay, aCamera, px, py);
    }

    Object intersectionWith(Object aSphere, Object aRay) throws ReflectiveOperationException {
        return call(intersectionWith, aSphere, aRay);
    }

    Object findClosestIntersection(Object aScene, Object aRay) throws ReflectiveOperationException {
        return call(findClosestIntersection, aScene, aRay);
    }

    Object illuminate(Object aRenderer, Object aScene, Object aSphere, Object point, Object normal)
            throws ReflectiveOperationException {
        return call(illuminate, aRenderer, aScene, aSphere, point, normal);
    }

    Object objectHit(Object hit) throws ReflectiveOperationException {
        return call(getObjectHit, hit);
    }

    double distance(Object hit) throws ReflectiveOperationException {
        return (double) call(getDistance, hit);
    }

    Object location(Object hit) throws ReflectiveOperationException {
        return call(getLocation, hit);
    }

    Object normal(Object hit) throws ReflectiveOperationException {
        return call(getNormal, hit);
    }

    int toRgb(Object colour) throws ReflectiveOperationException {
        return (int) call(toRgb, colour);
    }

    /** x, y and z of a Vector3 (NaN for each when it is null). */
    double[] components(Object vector) throws ReflectiveOperationException {
        if (vector == null) {
            return new double[] {Double.NaN, Double.NaN, Double.NaN};
        }
        return new double[] {x.getDouble(vector), y.getDouble(vector), z.getDouble(vector)};
    }

    private static Object construct(Constructor<?> constructor, Object... arguments)
            throws ReflectiveOperationException {
        try {
            return constructor.newInstance(arguments);
        } catch (InvocationTargetException e) {
            throw new StudentCodeException(e.getCause());
        }
    }

    private static Object call(Method method, Object target, Object... arguments) throws ReflectiveOperationException {
        try {
            return method.invoke(target, arguments);
        } catch (InvocationTargetException e) {
            throw new StudentCodeException(e.getCause());
        }
    }

    /** What the student's (or the starter's) code threw. */
    static final class StudentCodeException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        StudentCodeException(Throwable cause) {
            super(cause);
        }
    }
}
