package gfx.tick1.command.shared.coverage;

import gfx.tick1.engine.scene.BundledScenes;
import gfx.tick1.engine.scene.SceneException;
import gfx.tick1.engine.scene.SceneLoader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

/**
 * The scenes {@code grade} grades on, named as it names them: tick1.xml, then the hidden scene or
 * those of a folder.
 */
public final class GradingScenes {

    private GradingScenes() {
    }

    /** tick1.xml and the built-in hidden scene. */
    public static List<NamedScene> builtIn() {
        return BundledScenes.GRADING.stream().map(name -> new NamedScene(name, BundledScenes.load(name))).toList();
    }

    /**
     * tick1.xml and every *.xml of {@code folder} in name order, as {@code grade --scenes} reads them.
     *
     * @throws SceneException when a scene cannot be read, or has no point light to grade with
     * @throws IOException    when the folder cannot be listed or holds no scene
     */
    public static List<NamedScene> withFolder(Path folder) throws IOException {
        if (!Files.isDirectory(folder)) {
            throw new IOException(folder + ": not a folder (--scenes wants a folder of *.xml scenes)");
        }
        List<Path> files;
        try (Stream<Path> listed = Files.list(folder)) {
            files = listed.filter(f -> f.toString().endsWith(".xml") && Files.isRegularFile(f))
                    .sorted(Comparator.comparing(Path::toString)).toList();
        }
        if (files.isEmpty()) {
            throw new IOException(folder + ": no *.xml scene files in the folder");
        }
        List<NamedScene> scenes = new ArrayList<>(List.of(new NamedScene(BundledScenes.TICK1,
                BundledScenes.load(BundledScenes.TICK1))));
        for (Path file : files) {
            NamedScene scene = new NamedScene(file.toString(), new SceneLoader(file, false).getScene());
            if (scene.scene().getPointLight() == null) {
                throw new SceneException(file + ": no <point-light>: the starter code needs one to grade with");
            }
            scenes.add(scene);
        }
        return scenes;
    }
}
