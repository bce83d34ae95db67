package gfx.tick1;

import static com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAPackage;
import static com.tngtech.archunit.core.domain.JavaClass.Predicates.simpleNameEndingWith;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.Architectures.layeredArchitecture;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.assertj.core.api.Assertions.assertThat;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import gfx.tick1.cli.MainClass;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * How the packages may depend on one another. The engine is layered, maths at the bottom:
 * {@code math <- scene <- render <- fast}; images, file-error wording and the commands' shared
 * help sit beside it; the commands use all of them, and the start-up ({@code gfx.tick1}: Tick1,
 * the render command) uses the commands. Nothing depends on the start-up.
 */
class ArchitectureTest {

    private static JavaClasses program;

    @BeforeAll
    static void importTheProgram() {
        program = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("gfx.tick1");
    }

    @Test
    void noPackagesDependOnEachOtherInACycle() {
        slices().matching("gfx.tick1.(**)").should().beFreeOfCycles().check(program);
    }

    @Test
    void eachLayerIsUsedOnlyByTheLayersAboveIt() {
        layeredArchitecture().consideringOnlyDependenciesInLayers()
                .layer("Maths").definedBy("gfx.tick1.math..")
                .layer("Scenes").definedBy("gfx.tick1.scene..")
                .layer("Rendering").definedBy("gfx.tick1.render..")
                .layer("Fast rendering").definedBy("gfx.tick1.fast..")
                .layer("Images").definedBy("gfx.tick1.image..")
                .layer("File errors").definedBy("gfx.tick1.io..")
                .layer("Command help").definedBy("gfx.tick1.cli..")
                .layer("Commands").definedBy("gfx.tick1.compare..", "gfx.tick1.diagnose..", "gfx.tick1.diff..",
                        "gfx.tick1.grade..", "gfx.tick1.preview..", "gfx.tick1.bench..", "gfx.tick1.starter..")
                .layer("Tools").definedBy("gfx.tick1.tools..")
                .layer("Start-up").definedBy("gfx.tick1")

                .whereLayer("Start-up").mayNotBeAccessedByAnyLayer()
                .whereLayer("Tools").mayNotBeAccessedByAnyLayer()
                .whereLayer("Commands").mayOnlyBeAccessedByLayers("Start-up")
                .whereLayer("Command help").mayOnlyBeAccessedByLayers("Commands", "Start-up")
                .whereLayer("Fast rendering").mayOnlyBeAccessedByLayers("Commands", "Start-up")
                .whereLayer("Rendering").mayOnlyBeAccessedByLayers("Fast rendering", "Commands", "Tools", "Start-up")
                .whereLayer("Scenes").mayOnlyBeAccessedByLayers("Rendering", "Fast rendering", "Commands", "Tools",
                        "Start-up")
                .whereLayer("Maths").mayOnlyBeAccessedByLayers("Scenes", "Rendering", "Fast rendering", "Commands",
                        "Tools", "Start-up")
                .whereLayer("Images").mayOnlyBeAccessedByLayers("Commands", "Tools", "Start-up")
                .whereLayer("File errors").mayOnlyBeAccessedByLayers("Scenes", "Images", "Commands", "Start-up")
                .check(program);
    }

    @Test
    void theEngineUsesNoCommand() {
        noClasses().that().resideInAnyPackage("gfx.tick1.math..", "gfx.tick1.scene..", "gfx.tick1.render..",
                        "gfx.tick1.fast..", "gfx.tick1.image..", "gfx.tick1.io..")
                .should().dependOnClassesThat(resideInAPackage("gfx.tick1..").and(simpleNameEndingWith("Command")))
                .orShould().dependOnClassesThat().haveFullyQualifiedName(MainClass.NAME)
                .check(program);
    }

    @Test
    void aCohortsRecordsDoNotDependOnTheGradeCommand() {
        noClasses().that().resideInAPackage("gfx.tick1.grade.cohort..")
                .should().dependOnClassesThat().resideInAPackage("gfx.tick1.grade")
                .check(program);
    }

    @Test
    void theMainClassNamedForFreshProcessesIsTheEntryPoint() {
        assertThat(MainClass.NAME).isEqualTo(Tick1.class.getName());
    }
}
