package gfx.tick1.command.shared.diagnosis;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.engine.scene.BundledScenes;
import gfx.tick1.engine.scene.Scene;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The scene files one slip away from the one asked for, as {@code diagnose} tries them. */
class SceneChangeTest {

    private static final Scene TICK1 = BundledScenes.load(BundledScenes.TICK1);
    private static final Scene EXAMPLE = BundledScenes.load(BundledScenes.BASIC);

    private static List<String> described() {
        return SceneChange.around(TICK1, EXAMPLE).stream().map(change -> change.describe("asked")).toList();
    }

    @Test
    void everyChangeIsAnotherScene() {
        assertThat(SceneChange.around(TICK1, EXAMPLE)).as("the slips of tick1.xml").isNotEmpty()
                .noneMatch(change -> SceneChange.same(change.scene(), TICK1));
    }

    @Test
    void theExamplesValuesAreAmongTheSlips() {
        assertThat(described()).as("values kept from basic_scene.xml").contains("ambient #333333 where asked #555555",
                "the point light's colour #FFFFFF where asked #B3DDFF",
                "the point light's intensity 100 where asked 120",
                "the point light at (3, 3, 3) where asked (1, 3, 2)", "sphere 2's colour #FF0000 where asked #FF1D25");
    }

    @Test
    void aLostSignAndALeftOutCoordinateAreAmongTheSlips() {
        assertThat(described()).as("slips of a sphere's centre").contains(
                "sphere 1's centre (0.55, 0.16, 3.5) where asked (0.55, -0.16, 3.5)",
                "sphere 1's centre (0.55, 0, 3.5) where asked (0.55, -0.16, 3.5)",
                "sphere 2's centre (0.55, 0, 5) where asked (-0.55, 0, 5)");
    }

    @Test
    void aSceneIsTheSameAsItselfLoadedAgainAndNotAsAnother() {
        assertThat(SceneChange.same(TICK1, BundledScenes.load(BundledScenes.TICK1))).as("tick1.xml twice").isTrue();
        assertThat(SceneChange.same(TICK1, EXAMPLE)).as("tick1.xml and basic_scene.xml").isFalse();
    }
}
