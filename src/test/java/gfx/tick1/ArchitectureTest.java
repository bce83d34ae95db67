package gfx.tick1;

import static com.tngtech.archunit.core.domain.JavaClass.Predicates.resideInAnyPackage;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.classes;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.Architectures.layeredArchitecture;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.assertj.core.api.Assertions.assertThat;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import gfx.tick1.command.shared.cli.MainClass;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * How tick1's source is laid out, and how its packages may depend on one another.
 *
 * <p>{@code gfx.tick1} holds three groups. The <em>start-up</em> is {@code Tick1} (the program's
 * entry point, which builds the command line) and {@code tools} (the maintainers' entry points).
 * The <em>engine</em> ({@code engine.*}) is the ray tracer and its files: maths at the bottom,
 * {@code math <- scene <- render <- fast}, with images and file-error wording beside them. The
 * <em>commands</em> ({@code command.*}) are one package per subcommand, and
 * {@code command.shared.*}, what several commands use: the command-line help, the starter kit,
 * the diagnosis of an image, the reading of Java source and the grader. A command uses the engine
 * and the shared services, never another command; nothing but the start-up uses a command. The one
 * subcommand outside its own package is {@code vpl}: it lives with all of VPL in the grader's
 * {@code vpl}, which {@code grade --format vpl} uses too.
 */
class ArchitectureTest {

    private static final String[] ENGINE = {"gfx.tick1.engine.."};
    private static final String[] SHARED = {"gfx.tick1.command.shared.."};
    private static final String[] COMMANDS = {"gfx.tick1.command.bench..", "gfx.tick1.command.compare..",
        "gfx.tick1.command.coverage..", "gfx.tick1.command.diagnose..", "gfx.tick1.command.diff..",
        "gfx.tick1.command.grade..", "gfx.tick1.command.preview..", "gfx.tick1.command.render..",
        "gfx.tick1.command.starter.."};

    private static JavaClasses program;

    @BeforeAll
    static void importTheProgram() {
        program = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS)
                .importPackages("gfx.tick1");
    }

    @Test
    void everyClassBelongsToTheStartUpTheEngineOrTheCommands() {
        classes().should().resideInAnyPackage("gfx.tick1", "gfx.tick1.tools", "gfx.tick1.engine..",
                "gfx.tick1.command..").check(program);
    }

    @Test
    void theTopLevelFolderShowsOnlyTheThreeGroups() throws IOException {
        try (Stream<Path> entries = Files.list(Path.of("src/main/java/gfx/tick1"))) {
            assertThat(entries.map(entry -> entry.getFileName().toString()).sorted())
                    .as("src/main/java/gfx/tick1: the start-up (Tick1.java, tools), the engine and the commands")
                    .containsExactly("Tick1.java", "command", "engine", "tools");
        }
    }

    @Test
    void everyCommandPackageIsListedHere() throws IOException {
        try (Stream<Path> entries = Files.list(Path.of("src/main/java/gfx/tick1/command"))) {
            assertThat(entries.map(entry -> "gfx.tick1.command." + entry.getFileName() + "..")
                    .filter(name -> !name.equals("gfx.tick1.command.shared.."))
                    .sorted())
                    .as("the command packages that the rules below treat as commands")
                    .containsExactly(COMMANDS);
        }
    }

    @Test
    void noPackagesDependOnEachOtherInACycle() {
        slices().matching("gfx.tick1.(**)").should().beFreeOfCycles().check(program);
    }

    /**
     * Class files keep no trace of an import that only Javadoc uses, so the source's imports are
     * read as well: a reader sees a cycle there even when the compiler drops it.
     */
    @Test
    void noPackagesImportEachOtherInACycleInTheSourceJavadocIncluded() throws IOException {
        Map<String, Set<String>> imports = sourceImports(Path.of("src/main/java"));
        List<String> cycles = new ArrayList<>();
        for (String from : imports.keySet()) {
            for (String to : imports.get(from)) {
                if (reaches(imports, to, from, new TreeSet<>())) {
                    cycles.add(from + " -> " + to);
                }
            }
        }
        assertThat(cycles).as("imports between packages that lead back to the importing package").isEmpty();
    }

    @Test
    void theStartUpUsesTheCommandsWhichUseTheSharedServicesWhichUseTheEngine() {
        layeredArchitecture().consideringOnlyDependenciesInLayers()
                .layer("Start-up").definedBy("gfx.tick1", "gfx.tick1.tools..")
                .layer("Commands").definedBy(COMMANDS)
                .layer("Shared services").definedBy(SHARED)
                .layer("Engine").definedBy(ENGINE)

                .whereLayer("Start-up").mayNotBeAccessedByAnyLayer()
                .whereLayer("Commands").mayOnlyBeAccessedByLayers("Start-up")
                .whereLayer("Shared services").mayOnlyBeAccessedByLayers("Commands", "Start-up")
                .whereLayer("Engine").mayOnlyBeAccessedByLayers("Shared services", "Commands", "Start-up")
                .check(program);
    }

    @Test
    void noCommandUsesAnotherCommand() {
        for (String command : COMMANDS) {
            String[] others = Stream.of(COMMANDS).filter(other -> !other.equals(command)).toArray(String[]::new);
            noClasses().that().resideInAPackage(command)
                    .should().dependOnClassesThat(resideInAnyPackage(others))
                    .as(command + " uses no other command")
                    .check(program);
        }
    }

    @Test
    void theEngineIsLayeredWithTheMathsAtTheBottom() {
        layeredArchitecture().consideringOnlyDependenciesInLayers()
                .layer("Maths").definedBy("gfx.tick1.engine.math..")
                .layer("Scenes").definedBy("gfx.tick1.engine.scene..")
                .layer("Rendering").definedBy("gfx.tick1.engine.render..")
                .layer("Fast rendering").definedBy("gfx.tick1.engine.fast..")
                .layer("Images").definedBy("gfx.tick1.engine.image..")
                .layer("File errors").definedBy("gfx.tick1.engine.io..")

                .whereLayer("Fast rendering").mayNotBeAccessedByAnyLayer()
                .whereLayer("Rendering").mayOnlyBeAccessedByLayers("Fast rendering")
                .whereLayer("Scenes").mayOnlyBeAccessedByLayers("Rendering", "Fast rendering")
                .whereLayer("Maths").mayOnlyBeAccessedByLayers("Scenes", "Rendering", "Fast rendering")
                .whereLayer("Images").mayNotBeAccessedByAnyLayer()
                .whereLayer("File errors").mayOnlyBeAccessedByLayers("Scenes", "Images")
                .check(program);
    }

    @Test
    void theGraderIsLayeredUnderTheCommandsThatUseIt() {
        layeredArchitecture().consideringOnlyDependenciesInLayers()
                .layer("Cohort").definedBy("gfx.tick1.command.shared.grader.cohort..")
                .layer("VPL").definedBy("gfx.tick1.command.shared.grader.vpl..")
                .layer("Report").definedBy("gfx.tick1.command.shared.grader.report..")
                .layer("Look-alikes").definedBy("gfx.tick1.command.shared.grader.lookalike..")
                .layer("Grading").definedBy("gfx.tick1.command.shared.grader.grading..")
                .layer("Intake").definedBy("gfx.tick1.command.shared.grader.intake..")
                .layer("Sandbox").definedBy("gfx.tick1.command.shared.grader.sandbox..")
                .layer("Harness").definedBy("gfx.tick1.command.shared.grader.harness..")
                .layer("Records").definedBy("gfx.tick1.command.shared.grader.model..")
                .layer("Commands").definedBy(COMMANDS)
                .layer("Start-up").definedBy("gfx.tick1")

                .whereLayer("Cohort").mayOnlyBeAccessedByLayers("Commands")
                .whereLayer("VPL").mayOnlyBeAccessedByLayers("Commands", "Start-up")
                .whereLayer("Report").mayOnlyBeAccessedByLayers("Cohort", "Commands")
                // The cohort's result store keeps the code the look-alike check parsed, for the next run.
                .whereLayer("Look-alikes").mayOnlyBeAccessedByLayers("Report", "Cohort", "Commands")
                .whereLayer("Grading").mayOnlyBeAccessedByLayers("Report", "Cohort", "VPL", "Commands")
                .whereLayer("Intake").mayOnlyBeAccessedByLayers("Grading", "Cohort", "Commands")
                .whereLayer("Sandbox").mayOnlyBeAccessedByLayers("Grading", "Cohort", "VPL", "Commands")
                .whereLayer("Harness").mayOnlyBeAccessedByLayers("Sandbox", "Grading", "Cohort", "Commands")
                .check(program);
    }

    /**
     * The harness's classes are the only ones of tick1 on the class path of the student's JVM in the sandbox
     * ({@code StudentProcess} copies them into a jar of their own), so they may use the JDK and one another, and
     * nothing else of tick1 or of its libraries.
     */
    @Test
    void theHarnessThatRunsInTheSandboxNeedsOnlyTheJdk() {
        classes().that().resideInAPackage("gfx.tick1.command.shared.grader.harness..")
                .should().onlyDependOnClassesThat().resideInAnyPackage("java..", "javax..",
                        "gfx.tick1.command.shared.grader.harness..", "")
                .check(program);
    }

    @Test
    void theMainClassNamedForFreshProcessesIsTheEntryPoint() {
        assertThat(MainClass.NAME).isEqualTo(Tick1.class.getName());
    }

    private static final Pattern IMPORT = Pattern.compile("^import (?:static )?(gfx\\.tick1(?:\\.[a-z]\\w*)*)\\.[A-Z]",
            Pattern.MULTILINE);

    /** Each package of the source, with the other packages of tick1 its files import. */
    private static Map<String, Set<String>> sourceImports(Path root) throws IOException {
        Map<String, Set<String>> imports = new TreeMap<>();
        try (Stream<Path> files = Files.walk(root)) {
            for (Path file : files.filter(f -> f.toString().endsWith(".java")).toList()) {
                String own = root.relativize(file.getParent()).toString().replace('/', '.');
                Set<String> used = imports.computeIfAbsent(own, k -> new TreeSet<>());
                Matcher matcher = IMPORT.matcher(Files.readString(file));
                while (matcher.find()) {
                    if (!matcher.group(1).equals(own)) {
                        used.add(matcher.group(1));
                    }
                }
            }
        }
        return imports;
    }

    private static boolean reaches(Map<String, Set<String>> imports, String from, String target, Set<String> seen) {
        if (from.equals(target)) {
            return true;
        }
        if (!seen.add(from)) {
            return false;
        }
        for (String next : imports.getOrDefault(from, Set.of())) {
            if (reaches(imports, next, target, seen)) {
                return true;
            }
        }
        return false;
    }
}
