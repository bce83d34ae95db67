package gfx.tick1.command.shared.coverage;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.SceneException;
import java.io.IOException;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * The catalogued mistakes that tick1.xml and the built-in hidden scene catch together and that the
 * scenes of a {@code --scenes} folder do not: what the organiser's hidden scenes give up. tick1.xml
 * is graded too, but its image is public; the hidden scenes are the ones a student cannot tune
 * their code to.
 *
 * @param missed the mistakes given up, in the catalogue's order
 */
public record ScenesShortfall(Set<Variant> missed) {

    public ScenesShortfall {
        missed = missed.isEmpty() ? EnumSet.noneOf(Variant.class) : EnumSet.copyOf(missed);
    }

    /**
     * What the scenes of {@code folder} give up, in images of
     * {@code width} x {@code height}; empty when nothing is, or when {@code folder} is null or its
     * scenes cannot be read (the grade says why itself).
     */
    public static Optional<ScenesShortfall> of(Path folder, int width, int height) {
        if (folder == null) {
            return Optional.empty();
        }
        List<Scene> given;
        try {
            given = GradingScenes.withFolder(folder).stream().map(NamedScene::scene).skip(1).toList();
        } catch (IOException | SceneException e) {
            return Optional.empty();
        }
        Set<Variant> builtIn = CatalogueOnScenes.caught(GradingScenes.builtIn().stream().map(NamedScene::scene)
                .toList(), width, height);
        builtIn.removeAll(CatalogueOnScenes.caught(given, width, height));
        return builtIn.isEmpty() ? Optional.empty() : Optional.of(new ScenesShortfall(builtIn));
    }

    /** The one line to print: "the scenes of DIR catch 2 catalogued mistakes fewer than ...: they miss a; b (...)". */
    public String line(Path folder) {
        return "the scenes of " + folder + " catch " + missed.size() + " catalogued "
                + (missed.size() == 1 ? "mistake" : "mistakes") + " fewer than tick1.xml and the built-in hidden "
                + "scene: they miss " + String.join("; ", missed.stream().map(Variant::title).toList())
                + " (tick1 coverage --scenes " + folder + " says more)";
    }
}
