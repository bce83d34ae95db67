package gfx.tick1;

import static com.tngtech.archunit.base.DescribedPredicate.not;
import static com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAPackage;
import static com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAnyPackage;
import static com.tngtech.archunit.core.domain.JavaClass.Predicates.simpleNameEndingWith;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.classes;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.Architectures.layeredArchitecture;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.assertj.core.api.Assertions.assertThat;

import com.tngtech.archunit.base.DescribedPredicate;
import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import gfx.tick1.cli.MainClass;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * How the packages may depend on one another. The engine is layered, maths at the bottom:
 * {@code math <- scene <- render <- fast}; images, file-error wording and the commands' shared
 * help sit beside it; the diagnosis of an image (which known mistake it shows) stands on them; the
 * commands use all of them, and the start-up ({@code gfx.tick1}: Tick1, the render command) uses
 * the commands. Nothing depends on the start-up.
 */
class ArchitectureTest {

    /** A subcommand's class: {@code DiagnoseCommand} lives beside the diagnosis it runs, but is a command. */
    private static final DescribedPredicate<JavaClass> COMMAND = simpleNameEndingWith("Command");

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
                .layer("Diagnosis").definedBy(resideInAPackage("gfx.tick1.diagnose..").and(not(COMMAND)))
                .layer("Commands").definedBy(resideInAnyPackage("gfx.tick1.compare..", "gfx.tick1.diff..",
                        "gfx.tick1.grade..", "gfx.tick1.preview..", "gfx.tick1.bench..", "gfx.tick1.starter..")
                        .or(resideInAPackage("gfx.tick1.diagnose..").and(COMMAND)))
                .layer("Tools").definedBy("gfx.tick1.tools..")
                .layer("Start-up").definedBy("gfx.tick1")

                .whereLayer("Start-up").mayNotBeAccessedByAnyLayer()
                .whereLayer("Tools").mayNotBeAccessedByAnyLayer()
                .whereLayer("Commands").mayOnlyBeAccessedByLayers("Start-up")
                .whereLayer("Diagnosis").mayOnlyBeAccessedByLayers("Commands", "Start-up")
                .whereLayer("Command help").mayOnlyBeAccessedByLayers("Diagnosis", "Commands", "Start-up")
                .whereLayer("Fast rendering").mayOnlyBeAccessedByLayers("Diagnosis", "Commands",
                        "Start-up")
                .whereLayer("Rendering").mayOnlyBeAccessedByLayers("Fast rendering", "Diagnosis", "Commands", "Tools",
                        "Start-up")
                .whereLayer("Scenes").mayOnlyBeAccessedByLayers("Rendering", "Fast rendering", "Diagnosis", "Commands",
                        "Tools", "Start-up")
                .whereLayer("Maths").mayOnlyBeAccessedByLayers("Scenes", "Rendering", "Fast rendering", "Diagnosis",
                        "Commands", "Tools", "Start-up")
                .whereLayer("Images").mayOnlyBeAccessedByLayers("Diagnosis", "Commands", "Tools", "Start-up")
                .whereLayer("File errors").mayOnlyBeAccessedByLayers("Scenes", "Images", "Diagnosis", "Commands",
                        "Start-up")
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
    void theGradingHouseIsLayeredUnderItsCommands() {
        layeredArchitecture().consideringOnlyDependenciesInLayers()
                .layer("Grade commands").definedBy("gfx.tick1.grade")
                .layer("Cohort").definedBy("gfx.tick1.grade.cohort..")
                .layer("VPL").definedBy("gfx.tick1.grade.vpl..")
                .layer("Report").definedBy("gfx.tick1.grade.report..")
                .layer("Look-alikes").definedBy("gfx.tick1.grade.lookalike..")
                .layer("Grading").definedBy("gfx.tick1.grade.grading..")
                .layer("Intake").definedBy("gfx.tick1.grade.intake..")
                .layer("Sandbox").definedBy("gfx.tick1.grade.sandbox..")
                .layer("Harness").definedBy("gfx.tick1.grade.harness..")
                .layer("Records").definedBy("gfx.tick1.grade.model..")

                .whereLayer("Grade commands").mayNotBeAccessedByAnyLayer()
                .whereLayer("Cohort").mayOnlyBeAccessedByLayers("Grade commands")
                .whereLayer("VPL").mayOnlyBeAccessedByLayers("Grade commands")
                .whereLayer("Report").mayOnlyBeAccessedByLayers("Cohort", "Grade commands")
                .whereLayer("Look-alikes").mayOnlyBeAccessedByLayers("Report", "Grade commands")
                .whereLayer("Grading").mayOnlyBeAccessedByLayers("Report", "Cohort", "VPL", "Grade commands")
                .whereLayer("Intake").mayOnlyBeAccessedByLayers("Cohort", "Grade commands")
                .whereLayer("Sandbox").mayOnlyBeAccessedByLayers("Grading", "Cohort", "VPL", "Grade commands")
                .whereLayer("Harness").mayOnlyBeAccessedByLayers("Sandbox", "Grading", "Cohort", "Grade commands")
                .check(program);
    }

    /**
     * The harness's classes are the only ones of tick1 on the class path of the student's JVM in the sandbox
     * ({@code StudentProcess} copies them into a jar of their own), so they may use the JDK and one another, and
     * nothing else of tick1 or of its libraries.
     */
    @Test
    void theHarnessThatRunsInTheSandboxNeedsOnlyTheJdk() {
        classes().that().resideInAPackage("gfx.tick1.grade.harness..")
                .should().onlyDependOnClassesThat().resideInAnyPackage("java..", "javax..", "gfx.tick1.grade.harness..",
                        "")
                .check(program);
    }

    @Test
    void theMainClassNamedForFreshProcessesIsTheEntryPoint() {
        assertThat(MainClass.NAME).isEqualTo(Tick1.class.getName());
    }
}
