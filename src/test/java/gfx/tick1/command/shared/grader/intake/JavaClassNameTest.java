package gfx.tick1.command.shared.grader.intake;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** The first declared class of a source, found whatever comes before it, in one pass. */
class JavaClassNameTest {

    @Test
    void theFirstDeclaredClassIsFound() {
        assertThat(JavaClassName.of("package gfx.tick1;\n\nimport java.util.List;\n\npublic class Sphere extends "
                + "SceneObject {\n class Inner {}\n}")).isEqualTo("Sphere");
    }

    @Test
    void commentsStringsAndClassLiteralsAreNotDeclarations() {
        assertThat(JavaClassName.of("// class Sphere\n/* class Sphere */\n/** {@code class Sphere} */\n"
                + "@Note(\"class Sphere\") final class Renderer { Object o = Sphere.class; char q = '\"'; }"))
                .isEqualTo("Renderer");
        assertThat(JavaClassName.of("String s = \"\"\"\n class Sphere\n\"\"\";\nclass Renderer {}"))
                .isEqualTo("Renderer");
    }

    @Test
    void aFileWithoutAClassHasNone() {
        assertThat(JavaClassName.of("package gfx.tick1;\ninterface Shape {}\n")).isNull();
        assertThat(JavaClassName.of("/* never closed class Sphere")).isNull();
    }

    @Test
    void aFloodOfCommentsBeforeTheClassIsScannedWithoutRecursion() {
        assertThat(JavaClassName.of("//\n".repeat(200_000) + "/* x */".repeat(50_000) + "class Sphere {}"))
                .isEqualTo("Sphere");
    }
}
