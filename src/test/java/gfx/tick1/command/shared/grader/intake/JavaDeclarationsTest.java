package gfx.tick1.command.shared.grader.intake;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.intake.JavaDeclarations.PackageClause;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * What a Java source declares, its package and its first class, read as javac reads it in one
 * bounded pass, whatever the file is made of.
 */
class JavaDeclarationsTest {

    private static final String BODY = "\nimport java.util.List;\npublic class Sphere { }\n";

    /** How many looks per character a one-pass scan may take; one that went back over the file takes thousands. */
    private static final int LOOKS_PER_CHARACTER = 4;

    private static Optional<String> firstClass(String code) {
        return JavaDeclarations.firstClassOf(code);
    }

    @Test
    void everyWayJavacAcceptsThePackageDeclarationIsThePackage() {
        List<String> heads = List.of("package gfx.tick1;", "  \n\t\fpackage gfx.tick1 ;",
                "// the tick\npackage gfx.tick1;", "/* a\n * block\n */ package gfx.tick1;",
                "/** doc */\r\n// two\r\npackage  gfx . tick1\n;", "package gfx/* here */.tick1;",
                "package/**/gfx.tick1;", "\\u0070ackage gfx.tick1;", "package gfx\\u002etick1\\u003b",
                "\\uuuu0070ackage gfx.tick1;", "// a comment that ends at a CR\rpackage gfx.tick1;");
        assertThat(heads).allSatisfy(head -> assertThat(JavaDeclarations.packageOf(head + BODY)).as(head)
                .isEqualTo(new PackageClause.Declared("gfx.tick1")));
    }

    @Test
    void anotherPackageIsReadAsDeclared() {
        assertThat(JavaDeclarations.packageOf("package tick1;" + BODY)).as("package tick1;")
                .isEqualTo(new PackageClause.Declared("tick1"));
        assertThat(JavaDeclarations.packageOf("package gfx . tick2 ;" + BODY)).as("package gfx . tick2 ;")
                .isEqualTo(new PackageClause.Declared("gfx.tick2"));
        assertThat(JavaDeclarations.packageOf("package gfx.tick1.sub;" + BODY)).as("package gfx.tick1.sub;")
                .isEqualTo(new PackageClause.Declared("gfx.tick1.sub"));
    }

    @Test
    void whatIsNotAPackageDeclarationDeclaresNoPackage() {
        List<String> heads = List.of("", "import java.util.List;", "package gfx.tick1", "packagegfx.tick1;",
                "/* never closed package gfx.tick1;", "// package gfx.tick1;", "\\\\u0070ackage gfx.tick1;",
                "package gfx..tick1;", "package .gfx.tick1;", "package 1gfx.tick1;", "Package gfx.tick1;");
        assertThat(heads).allSatisfy(head -> assertThat(JavaDeclarations.packageOf(head + "\nclass X { }"))
                .as(head).isEqualTo(new PackageClause.Undeclared()));
    }

    @Test
    void aPackageDeclarationBeyondTheScanCapIsRefusedByTheCap() {
        String flood = "//\n".repeat(JavaDeclarations.PACKAGE_SCAN_CAP / 3 + 1);
        assertThat(JavaDeclarations.packageOf(flood + "package gfx.tick1;" + BODY)).as("after a flood of comments")
                .isEqualTo(new PackageClause.BeyondCap());
        assertThat(JavaDeclarations.packageOf("package gfx" + " ".repeat(1 << 20))).as("a declaration never ended")
                .isEqualTo(new PackageClause.BeyondCap());
    }

    @Test
    void aFewThousandCommentLinesBeforeThePackageAreReadWithoutRecursion() {
        assertThat(JavaDeclarations.packageOf("//\n".repeat(1_600) + "/* x */".repeat(800) + "\n".repeat(1_700)
                + "package gfx.tick1;" + BODY)).isEqualTo(new PackageClause.Declared("gfx.tick1"));
    }

    @Test
    void theFirstDeclaredClassIsFound() {
        assertThat(firstClass("package gfx.tick1;\n\nimport java.util.List;\n\npublic class Sphere extends "
                + "SceneObject {\n class Inner {}\n}")).contains("Sphere");
    }

    @Test
    void commentsStringsAndClassLiteralsAreNotClassDeclarations() {
        assertThat(firstClass("// class Sphere\n/* class Sphere */\n/** {@code class Sphere} */\n"
                + "@Note(\"class Sphere\") final class Renderer { Object o = Sphere.class; char q = '\"'; }"))
                .as("comments, a string and a class literal before the declaration").contains("Renderer");
        assertThat(firstClass("String s = \"\"\"\n class Sphere\n\"\"\";\nclass Renderer {}"))
                .as("a text block before the declaration").contains("Renderer");
    }

    @Test
    void aFileWithoutAClassHasNone() {
        assertThat(firstClass("package gfx.tick1;\ninterface Shape {}\n")).as("an interface").isEmpty();
        assertThat(firstClass("/* never closed class Sphere")).as("an unclosed comment").isEmpty();
    }

    @Test
    void aFloodOfCommentsBeforeTheClassIsScannedWithoutRecursion() {
        assertThat(firstClass("//\n".repeat(200_000) + "/* x */".repeat(50_000) + "class Sphere {}"))
                .contains("Sphere");
    }

    @Test
    void aClassBeyondTheScanCapIsNotLookedFor() {
        String flood = " ".repeat(JavaDeclarations.CLASS_SCAN_CAP);
        assertThat(firstClass(flood + "class Sphere {}")).isEmpty();
    }

    @Test
    void megabytesOfCommentOpenersAreReadInOnePass() {
        String code = "/*/".repeat(3 << 20) + "*/ /" + "/*".repeat(2 << 20);
        assertOnePass(code);
    }

    @Test
    void megabytesOfUnicodeEscapeOpenersAreReadInOnePass() {
        String code = "/*" + ("\\" + "u".repeat(1000) + "00").repeat(4_000) + "\\\\u".repeat(1 << 20)
                + "\\u002a\\u002f" + "\\uuu0020".repeat(1 << 19);
        assertOnePass(code);
    }

    @Test
    void megabytesOfLiteralOpenersAreReadInOnePass() {
        String code = "\"\"\"\\\"\"".repeat(1 << 20) + "'\\".repeat(2 << 20);
        assertOnePass(code);
    }

    @Test
    void aFileOfManyMegabytesCostsNoMoreThanTheCap() {
        String code = "/*/".repeat(3 << 20);
        JavaDeclarations classScan = JavaDeclarations.scanning(code, JavaDeclarations.CLASS_SCAN_CAP);
        classScan.firstClass();
        assertThat(classScan.visits()).as("looks for the first class in " + code.length() + " characters")
                .isLessThanOrEqualTo((long) LOOKS_PER_CHARACTER * JavaDeclarations.CLASS_SCAN_CAP);
        JavaDeclarations packageScan = JavaDeclarations.scanning(code, JavaDeclarations.PACKAGE_SCAN_CAP);
        packageScan.packageClause();
        assertThat(packageScan.visits()).as("looks for the package in " + code.length() + " characters")
                .isLessThanOrEqualTo((long) LOOKS_PER_CHARACTER * JavaDeclarations.PACKAGE_SCAN_CAP);
    }

    /** Both questions, asked of the whole of {@code code} with no cap, take a few looks per character. */
    private static void assertOnePass(String code) {
        assertThat(code.length()).as("the file's length").isGreaterThan(4 << 20);
        JavaDeclarations classScan = JavaDeclarations.scanning(code, Integer.MAX_VALUE);
        classScan.firstClass();
        assertThat(classScan.visits()).as("looks for the first class in " + code.length() + " characters")
                .isLessThanOrEqualTo((long) LOOKS_PER_CHARACTER * code.length());
        JavaDeclarations packageScan = JavaDeclarations.scanning(code, Integer.MAX_VALUE);
        packageScan.packageClause();
        assertThat(packageScan.visits()).as("looks for the package in " + code.length() + " characters")
                .isLessThanOrEqualTo((long) LOOKS_PER_CHARACTER * code.length());
    }
}
