package gfx.tick1.command.shared.behaviour;

import gfx.tick1.command.shared.grader.sandbox.StudentProcess.Outcome;
import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.io.Counted;
import gfx.tick1.engine.render.GoldenImages;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.scene.BundledScenes;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * The handout's two scenes drawn by a student's whole code, render and trace included, at the
 * handout's size, against ours pixel for pixel: what shows that an edit of a member the behaviour
 * check does not call (a progress line removed, locals inlined in trace) changes no image of them.
 * {@code differences} says, one line a scene, where an image is not ours; none when all are.
 */
public record DrawnScenes(List<String> differences) {

    /** The scenes drawn: the two a student renders with the kit. */
    public static final List<String> SCENES = BundledScenes.STUDENT_SCENES;

    public DrawnScenes {
        differences = List.copyOf(differences);
    }

    /** Whether every scene was drawn as ours. */
    public boolean asOurs() {
        return differences.isEmpty();
    }

    /** Writes the scenes into {@code folder}, under their own names. */
    static void write(Path folder) throws IOException {
        for (String name : SCENES) {
            BundledScenes.extract(name, folder);
        }
    }

    /**
     * Our images of {@link #SCENES}, in that order, drawn in a thread of their own: started before the
     * student's code runs, they are ready by the time it has drawn its own.
     */
    static CompletableFuture<List<BufferedImage>> drawOurs() {
        return CompletableFuture.supplyAsync(() -> SCENES.stream()
                .map(name -> new ReferenceRenderer(GoldenImages.WIDTH, GoldenImages.HEIGHT)
                        .render(BundledScenes.load(name))).toList(), task -> {
                            Thread drawing = new Thread(task, "tick1 our scenes");
                            drawing.setDaemon(true);
                            drawing.start();
                        });
    }

    /** What became of the scenes, in {@link #SCENES} order, against {@code ours}, our images of them. */
    static DrawnScenes of(List<Outcome> outcomes, List<BufferedImage> ours) {
        List<String> differences = new ArrayList<>();
        for (int i = 0; i < SCENES.size(); i++) {
            String name = SCENES.get(i);
            if (!(outcomes.get(i) instanceof Outcome.Rendered rendered)) {
                differences.add("your code draws no image of " + name + ": "
                        + ((Outcome.Failed) outcomes.get(i)).reason().lines().findFirst().orElse(""));
                continue;
            }
            ImageDifference difference = ImageDifference.between(ours.get(i), rendered.image());
            int differing = difference.differingPixels();
            if (differing > 0) {
                differences.add("your code draws " + name + " unlike ours: " + differing + " of its "
                        + Counted.of(difference.totalPixels(), "pixel") + (differing == 1 ? " differs" : " differ")
                        + ", within pixels " + difference.boundingBox());
            }
        }
        return new DrawnScenes(differences);
    }
}
