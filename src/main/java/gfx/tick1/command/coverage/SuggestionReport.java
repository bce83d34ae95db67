package gfx.tick1.command.coverage;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.coverage.SceneSearch;
import java.nio.file.Path;
import java.util.List;

/** What {@code --suggest} says of the scene it wrote: what it catches, and how it was found. */
final class SuggestionReport {

    private SuggestionReport() {
    }

    static List<String> lines(SceneSearch.Suggestion suggestion, Path file) {
        int showable = suggestion.caught().size() + suggestion.missed().size();
        String caught = suggestion.missed().isEmpty()
                ? "it catches all " + showable + " mistakes a fair scene of the tick can show"
                : "it catches " + suggestion.caught().size() + " of the " + showable + " mistakes a fair scene of "
                        + "the tick can show, the most of the candidates tried; it misses "
                        + String.join("; ", suggestion.missed().stream().map(Variant::title).toList());
        return List.of("Wrote " + CoverageTable.plain(file.toString()) + ", a scene to grade on as a hidden scene: "
                + caught + ". The handout's six steps taken literally, a correct answer, pass it, and its two "
                + "references are the same image.",
                "How it was found: candidate " + suggestion.candidate() + " of a search with a fixed seed, the same "
                        + "on every run. Each candidate keeps tick1.xml's spheres and ambient light, moves the light, "
                        + "adds a sphere farther away and one behind the camera whose surface passes through it "
                        + "(which a root accepted at s = 0 hits at the camera), and is kept when its images catch "
                        + "every such mistake.");
    }
}
