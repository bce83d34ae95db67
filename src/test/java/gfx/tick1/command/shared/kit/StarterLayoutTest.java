package gfx.tick1.command.shared.kit;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.diff.LineDiff;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The starter kit's two student files and our Sphere.java and Renderer.java are the same text
 * outside the TODO regions: a line diff between them changes only lines inside a TODO region
 * (from a {@code // TODO} line to the next one or to the end of its method), apart from the
 * package and import lines, since ours live in packages. So a student who diffs their file
 * against ours sees their solution against ours, and nothing else.
 */
class StarterLayoutTest {

    @ParameterizedTest(name = "{0}")
    @CsvSource({"Sphere, src/main/java/gfx/tick1/engine/scene/Sphere.java, 3",
        "Renderer, src/main/java/gfx/tick1/engine/render/Renderer.java, 4"})
    void theKitAndOurFileDifferOnlyInsideTheTodoRegions(String className, Path ours, int todos) throws IOException {
        List<String> kit = withoutPackageAndImports(StarterKit.source(className).lines().toList());
        List<String> reference = withoutPackageAndImports(Files.readAllLines(ours));
        boolean[] inRegion = todoRegions(kit);
        assertThat(kit.stream().filter(line -> line.contains("// TODO"))).as("the kit's TODOs").hasSize(todos);

        int kitLine = 0; // index in the kit of the next line the edits reach
        List<LineDiff.Line> edits = LineDiff.edits(kit, reference);
        for (int i = 0; i < edits.size(); i++) {
            LineDiff.Line edit = edits.get(i);
            if (edit.kind() == '-') {
                assertThat(inRegion[kitLine]).as("kit line %d \"%s\" differs from %s outside a TODO region",
                        kitLine + 1, edit.text(), ours).isTrue();
            } else if (edit.kind() == '+') {
                boolean besideRegion = (kitLine < kit.size() && inRegion[kitLine])
                        || (kitLine > 0 && inRegion[kitLine - 1]);
                assertThat(besideRegion).as("%s adds \"%s\" before kit line %d, outside a TODO region",
                        ours, edit.text(), kitLine + 1).isTrue();
            }
            if (edit.kind() != '+') {
                kitLine++;
            }
        }
    }

    /** For each line of the kit: whether it is in a TODO region. */
    private static boolean[] todoRegions(List<String> kit) {
        boolean[] inRegion = new boolean[kit.size()];
        boolean open = false;
        for (int i = 0; i < kit.size(); i++) {
            String line = kit.get(i);
            if (line.strip().startsWith("// TODO")) {
                open = true;
            } else if (line.equals("    }")) { // the end of the method
                open = false;
            }
            inRegion[i] = open;
        }
        return inRegion;
    }

    private static List<String> withoutPackageAndImports(List<String> lines) {
        List<String> kept = new ArrayList<>();
        for (String line : lines) {
            if (!(line.startsWith("package ") || line.startsWith("import ")) && !(kept.isEmpty() && line.isBlank())) {
                kept.add(line);
            }
        }
        return kept;
    }
}
