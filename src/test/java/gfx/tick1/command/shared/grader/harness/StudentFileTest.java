package gfx.tick1.command.shared.grader.harness;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The package a student's file declares, as javac reads it, found in one bounded pass. */
class StudentFileTest {

    private static final String BODY = "\nimport java.util.List;\npublic class Sphere { }\n";

    private static String problem(String code) {
        return StudentFile.packageProblem("Sphere.java", code);
    }

    @Test
    void everyWayJavacAcceptsTheDeclarationIsThePackage() {
        List<String> heads = List.of("package gfx.tick1;", "  \n\t\fpackage gfx.tick1 ;",
                "// the tick\npackage gfx.tick1;", "/* a\n * block\n */ package gfx.tick1;",
                "/** doc */\r\n// two\r\npackage  gfx . tick1\n;", "package gfx/* here */.tick1;",
                "package/**/gfx.tick1;", "\\u0070ackage gfx.tick1;", "package gfx\\u002etick1\\u003b",
                "\\uuuu0070ackage gfx.tick1;", "// a comment that ends at a CR\rpackage gfx.tick1;");
        assertThat(heads).allSatisfy(head -> assertThat(problem(head + BODY)).as(head).isNull());
    }

    @Test
    void anotherPackageIsNamedAsDeclared() {
        assertThat(problem("package tick1;" + BODY)).endsWith("but it declares package tick1");
        assertThat(problem("package gfx . tick2 ;" + BODY)).endsWith("but it declares package gfx.tick2");
        assertThat(problem("package gfx.tick1.sub;" + BODY)).endsWith("but it declares package gfx.tick1.sub");
    }

    @Test
    void whatIsNotADeclarationDeclaresNoPackage() {
        List<String> heads = List.of("", "import java.util.List;", "package gfx.tick1", "packagegfx.tick1;",
                "/* never closed package gfx.tick1;", "// package gfx.tick1;", "\\\\u0070ackage gfx.tick1;",
                "package gfx..tick1;", "package .gfx.tick1;", "package 1gfx.tick1;", "Package gfx.tick1;");
        assertThat(heads).allSatisfy(head -> assertThat(problem(head + "\nclass X { }"))
                .as(head).endsWith("but it declares no package"));
    }

    @Test
    void aDeclarationBeyondTheScanCapIsRefusedByTheCap() {
        String flood = "//\n".repeat(PackageDeclaration.SCAN_CAP / 3 + 1);
        assertThat(problem(flood + "package gfx.tick1;" + BODY)).contains("declares no package within its first");
        String unended = "package gfx" + " ".repeat(1 << 20);
        assertThat(problem(unended)).contains("declares no package within its first");
    }

    @Test
    void aFewThousandCommentLinesBeforeTheDeclarationAreReadWithoutRecursion() {
        assertThat(problem("//\n".repeat(1_600) + "/* x */".repeat(800) + "\n".repeat(1_700)
                + "package gfx.tick1;" + BODY)).isNull();
    }

    @Test
    void aLongDeclaredNameIsQuotedInPart() {
        String name = "a".repeat(5000);
        assertThat(problem("package " + name + ";")).hasSizeLessThan(400).contains("(5000 characters)");
    }
}
