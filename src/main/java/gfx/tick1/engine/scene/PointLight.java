package gfx.tick1.engine.scene;

import gfx.tick1.engine.math.Vector3;

/** A point light radiating its intensity equally in all directions. */
public final class PointLight {

    private final Vector3 position;
    private final Vector3 colour;
    private final double intensity;

    public PointLight(Vector3 position, Vector3 colour, double intensity) {
        this.position = position;
        this.colour = colour;
        this.intensity = intensity;
    }

    public Vector3 getPosition() {
        return position;
    }

    public Vector3 getColour() {
        return colour;
    }

    public double getIntensity() {
        return intensity;
    }

    /**
     * The illumination I at a distance d: the inverse-square law, with the power spread over the
     * sphere of area 4 pi d^2 (written in the starter code's order, pi * 4 * d^2).
     */
    public Vector3 getIlluminationAt(double distance) {
        return colour.scale(intensity / (Math.PI * 4 * Math.pow(distance, 2)));
    }
}
