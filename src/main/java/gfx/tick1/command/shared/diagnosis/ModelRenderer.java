package gfx.tick1.command.shared.diagnosis;

import gfx.tick1.command.shared.behaviour.Models;
import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.engine.math.Ray;
import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.render.Camera;
import gfx.tick1.engine.scene.RaycastHit;
import gfx.tick1.engine.scene.Scene;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.stream.IntStream;

/**
 * Images of a scene as {@link Models} with several entries at once render it: the slips of
 * intersectionWith or illuminate made together, as {@code grade} names two entries "together".
 * Render's own slips (rounding, rows upside down, red and blue swapped) are {@link VariantRenderer}'s
 * alone: no model of the two methods holds them.
 */
public final class ModelRenderer {

    private final int width, height;

    public ModelRenderer(int width, int height) {
        this.width = width;
        this.height = height;
    }

    /**
     * The pixels (0xRRGGBB, row by row from the top) of {@code scene} as each model renders it, in
     * the order given, rows shared among the cores.
     *
     * @throws IllegalArgumentException for a model with an entry of render's
     */
    public List<int[]> render(Scene scene, List<Set<Variant>> models) {
        for (Set<Variant> model : models) {
            if (model.stream().anyMatch(variant -> variant.method() == Variant.Method.RENDER)) {
                throw new IllegalArgumentException(model + ": render's slips are not models of the methods");
            }
        }
        Camera camera = new Camera(width, height);
        List<int[]> pixels = new ArrayList<>();
        List<Boolean> ownHits = new ArrayList<>();
        for (Set<Variant> model : models) {
            pixels.add(new int[width * height]);
            ownHits.add(model.stream().anyMatch(variant -> variant.method() == Variant.Method.INTERSECTION_WITH));
        }
        IntStream.range(0, height).parallel().forEach(y -> {
            for (int x = 0; x < width; x++) {
                Ray ray = camera.castRay(x, y);
                RaycastHit nearHit = scene.findClosestIntersection(ray);
                for (int m = 0; m < models.size(); m++) {
                    Set<Variant> model = models.get(m);
                    RaycastHit hit = ownHits.get(m) ? VariantRenderer.closestHit(scene, ray, model) : nearHit;
                    Vector3 colour = VariantRenderer.shade(scene, hit, Variant.CORRECT, model);
                    pixels.get(m)[y * width + x] = colour.toRGB() & 0xFFFFFF;
                }
            }
        });
        return pixels;
    }

    /** One model's pixels, as {@link #render(Scene, List)}. */
    public int[] render(Scene scene, Set<Variant> model) {
        return render(scene, List.of(model)).get(0);
    }
}
