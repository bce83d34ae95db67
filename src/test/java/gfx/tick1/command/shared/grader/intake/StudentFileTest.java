package gfx.tick1.command.shared.grader.intake;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * What the tester says about the package a student's file declares; how the declaration is read is
 * {@link JavaDeclarationsTest}'s.
 */
class StudentFileTest {

    private static final String BODY = "\nimport java.util.List;\npublic class Sphere { }\n";

    private static Optional<String> problem(String code) {
        return StudentFile.packageProblem("Sphere.java", code);
    }

    @Test
    void theStartersPackageIsNoProblem() {
        assertThat(problem("// the tick\npackage gfx . tick1;" + BODY)).as("package gfx.tick1;").isEmpty();
    }

    @Test
    void anotherPackageIsNamedAsDeclared() {
        assertThat(problem("package tick1;" + BODY)).get().asString()
                .isEqualTo("Sphere.java: the tester needs the file in package gfx.tick1 (its first line \"package "
                        + "gfx.tick1;\", as in the starter code), but it declares package tick1");
        assertThat(problem("package gfx . tick2 ;" + BODY)).get().asString()
                .endsWith("but it declares package gfx.tick2");
        assertThat(problem("package gfx.tick1.sub;" + BODY)).get().asString()
                .endsWith("but it declares package gfx.tick1.sub");
    }

    @Test
    void noDeclarationIsSaid() {
        assertThat(problem("import java.util.List;\nclass X { }")).get().asString()
                .endsWith("but it declares no package");
    }

    @Test
    void aDeclarationBeyondTheScanCapIsRefusedByTheCap() {
        String flood = "//\n".repeat(JavaDeclarations.PACKAGE_SCAN_CAP / 3 + 1);
        assertThat(problem(flood + "package gfx.tick1;" + BODY)).get().asString()
                .endsWith("but it declares no package within its first 65536 characters (comments and blank lines "
                        + "included)");
    }

    @Test
    void aLongDeclaredNameIsQuotedInPart() {
        String name = "a".repeat(5000);
        assertThat(problem("package " + name + ";")).get().asString().hasSizeLessThan(400)
                .contains("(5000 characters)");
    }
}
