package gfx.tick1.command.shared.grader.grading;

import gfx.tick1.command.shared.grader.sandbox.SceneBatch;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.scene.BundledScenes;
import gfx.tick1.engine.scene.Intersection;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneException;
import gfx.tick1.engine.scene.SceneLoader;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.stream.Stream;

/**
 * What every submission of one grade is graded against: the grading scenes, their reference
 * images, the image size and the limits. The scenes are read and copied once into a folder the
 * sandboxes can reach; each reference image is rendered once, when a student's image is first
 * compared with it, however many students are graded.
 */
public final class Grading {

    /**
     * One grading scene: a name to report it by, its file, the scene as the reference reads it,
     * and whether it is hidden (its content must not reach the student: no expected image, no
     * message text of the student's code).
     */
    public record CourseScene(String name, Path file, Scene scene, boolean hidden) {
        SceneBatch batch() {
            return hidden ? SceneBatch.HIDDEN : SceneBatch.PUBLIC;
        }
    }

    /** The limits and sizes that change a grade. */
    public record Limits(int width, int height, Duration timeLimit, int memoryMegabytes,
            ReferenceChoice referenceChoice) {
    }

    private final List<CourseScene> scenes;
    private final Limits limits;
    private final Map<String, CompletableFuture<BufferedImage>> references = new ConcurrentHashMap<>();

    private Grading(List<CourseScene> scenes, Limits limits) {
        this.scenes = List.copyOf(scenes);
        this.limits = limits;
    }

    /**
     * tick1.xml, then the hidden scene or the scenes of {@code extraScenes} (all hidden, or null
     * for the built-in one), each checked by the reference loader; the built-in ones are written
     * into {@code work}.
     *
     * @throws SceneException when a scene cannot be read or cannot be graded with
     * @throws IOException    when {@code extraScenes} is not a folder of scenes, or a copy fails
     */
    public static Grading prepare(Path work, Path extraScenes, Limits limits) throws IOException {
        Path bundled = Files.createDirectory(work.resolve("bundled"));
        List<CourseScene> scenes = new ArrayList<>();
        scenes.add(load(BundledScenes.TICK1, BundledScenes.extract(BundledScenes.TICK1, bundled), SceneBatch.PUBLIC));
        if (extraScenes == null) {
            scenes.add(load(BundledScenes.HIDDEN, BundledScenes.extract(BundledScenes.HIDDEN, bundled),
                    SceneBatch.HIDDEN));
        } else {
            if (!Files.isDirectory(extraScenes)) {
                throw new IOException(extraScenes + ": not a folder (--scenes wants a folder of *.xml scenes)");
            }
            try (Stream<Path> files = Files.list(extraScenes)) {
                List<Path> xml = files.filter(f -> f.toString().endsWith(".xml") && Files.isRegularFile(f))
                        .sorted(Comparator.comparing(Path::toString)).toList();
                if (xml.isEmpty()) {
                    throw new IOException(extraScenes + ": no *.xml scene files in the folder");
                }
                for (Path file : xml) {
                    scenes.add(load(file.toString(), file, SceneBatch.HIDDEN));
                }
            }
        }
        return new Grading(scenes, limits);
    }

    /**
     * Copies the scenes into {@code folder} for the student's processes: public ones to
     * public-scenes/, hidden ones to hidden-scenes/, as 0.xml, 1.xml, ... in order.
     */
    public void copyScenes(Path folder) throws IOException {
        for (SceneBatch kind : SceneBatch.values()) {
            Path batch = Files.createDirectory(folder.resolve(kind.folder()));
            int index = 0;
            for (CourseScene scene : scenes) {
                if (scene.batch() == kind) {
                    Files.copy(scene.file(), batch.resolve(index++ + ".xml"));
                }
            }
        }
    }

    private static CourseScene load(String name, Path file, SceneBatch batch) {
        Scene scene = new SceneLoader(file, false).getScene();
        if (scene.getPointLight() == null) {
            // The handout's illuminate() starts with scene.getPointLight().getPosition().
            throw new SceneException(file + ": no <point-light>: the starter code needs one to grade with");
        }
        return new CourseScene(name, file, scene, batch == SceneBatch.HIDDEN);
    }

    public List<CourseScene> scenes() {
        return scenes;
    }

    /** The scenes of one batch (public or hidden), in grading order. */
    List<CourseScene> batch(SceneBatch kind) {
        return scenes.stream().filter(scene -> scene.batch() == kind).toList();
    }

    /** The folder that {@link #copyScenes} made in {@code folder} for one batch's scenes. */
    static Path batchScenes(Path folder, SceneBatch kind) {
        return folder.resolve(kind.folder());
    }

    public Limits limits() {
        return limits;
    }

    /**
     * Starts rendering every reference image the grade compares with, on a thread of its own, so that they
     * are ready when the student's code has run: one student's grade leaves a core idle while the code
     * compiles and runs in its own process. A reference that fails here fails again, as ever, when compared.
     */
    public void renderReferencesAhead() {
        Thread ahead = new Thread(() -> {
            for (CourseScene scene : scenes) {
                for (Intersection intersection : limits.referenceChoice().intersections()) {
                    try {
                        reference(scene, intersection);
                    } catch (RuntimeException | Error e) {
                        return;
                    }
                }
            }
        }, "tick1-references-ahead");
        ahead.setDaemon(true);
        ahead.start();
    }

    /**
     * The reference image of {@code scene} with {@code intersection}: rendered by the first thread
     * that asks, and waited for by any other that asks meanwhile.
     */
    BufferedImage reference(CourseScene scene, Intersection intersection) {
        String key = scenes.indexOf(scene) + "/" + intersection;
        CompletableFuture<BufferedImage> mine = new CompletableFuture<>();
        CompletableFuture<BufferedImage> existing = references.putIfAbsent(key, mine);
        if (existing != null) {
            try {
                return existing.join();
            } catch (CompletionException e) {
                // Rendered ahead and failed there: the failure as the renderer threw it.
                Causes.throwIfUnchecked(e.getCause());
                throw e;
            }
        }
        try {
            mine.complete(new ReferenceRenderer(limits.width(), limits.height(), intersection).render(scene.scene()));
        } catch (RuntimeException | Error e) {
            mine.completeExceptionally(e);
            throw e;
        }
        return mine.join();
    }
}
