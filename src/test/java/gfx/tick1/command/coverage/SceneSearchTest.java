package gfx.tick1.command.coverage;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.coverage.CatalogueOnScenes;
import gfx.tick1.command.shared.coverage.SceneSearch;
import gfx.tick1.command.shared.diagnosis.SceneChange;
import gfx.tick1.command.shared.diagnosis.VariantRenderer;
import gfx.tick1.engine.image.ImageDifference;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.scene.BundledScenes;
import gfx.tick1.engine.scene.Intersection;
import gfx.tick1.engine.scene.Scene;
import java.awt.image.BufferedImage;
import java.util.EnumSet;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** The suggested scene catches what it claims, checked by rendering each model on it at the grading size. */
class SceneSearchTest {

    private static SceneSearch.Suggestion suggestion;

    @BeforeAll
    static void search() {
        suggestion = SceneSearch.find(640, 480);
    }

    @Test
    void theSuggestionCatchesEveryMistakeAFairSceneCanShow() {
        assertThat(suggestion.missed()).as("the mistakes the suggestion misses").isEmpty();
        assertThat(suggestion.caught()).isEqualTo(SceneSearch.showable());
    }

    @Test
    void eachModelRenderedOnTheSuggestionDiffersFromBothReferences() {
        Scene scene = suggestion.scene();
        BufferedImage handout = new ReferenceRenderer(640, 480, Intersection.HANDOUT).render(scene);
        BufferedImage robust = new ReferenceRenderer(640, 480, Intersection.ROBUST).render(scene);
        Set<Variant> rendered = EnumSet.copyOf(SceneSearch.showable());
        rendered.add(Variant.HANDOUT_SIX_STEPS);
        Map<Variant, BufferedImage> images = new VariantRenderer(640, 480).render(scene, rendered);
        for (Variant mistake : SceneSearch.showable()) {
            assertThat(ImageDifference.between(handout, images.get(mistake)).differingPixels())
                    .as("%s against the handout's reference", mistake).isPositive();
            assertThat(ImageDifference.between(robust, images.get(mistake)).differingPixels())
                    .as("%s against the robust reference", mistake).isPositive();
        }
        assertThat(ImageDifference.between(handout, images.get(Variant.HANDOUT_SIX_STEPS)).differingPixels())
                .as("the handout's six steps, a correct answer, pass the suggestion").isZero();
    }

    @Test
    void theSuggestionIsNotTick1Xml() {
        assertThat(SceneChange.same(suggestion.scene(), BundledScenes.load(BundledScenes.TICK1))).isFalse();
    }

    @Test
    void theShowableMistakesAreAllButThoseNoFairSceneShows() {
        assertThat(SceneSearch.showable()).doesNotContain(Variant.KD_SWAPPED_WITH_KS,
                Variant.UNCHECKED_NEGATIVE_SQUARE_ROOT, Variant.HIT_REJECTED_ON_A_NEGATIVE_ROOT)
                .contains(Variant.ROOTS_ACCEPTED_AT_ZERO, Variant.ROOTS_IN_FLOAT);
        assertThat(CatalogueOnScenes.mistakes()).containsAll(SceneSearch.showable());
    }
}
