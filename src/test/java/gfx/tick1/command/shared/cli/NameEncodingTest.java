package gfx.tick1.command.shared.cli;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class NameEncodingTest {

    // What Java 17 on Linux makes of "Zoë" started with LANG=C: each byte of the UTF-8 "ë" is U+FFFD.
    private static final String LOST = "Zo\uFFFD\uFFFD";

    @Test
    void namesThatArrivedWholeAreNoProblem() {
        assertThat(NameEncoding.problemFor("/home/zoë/Tick 1", "UTF-8", "diff", "Zoë/Sphere.java"))
                .as("a UTF-8 locale").isEmpty();
        assertThat(NameEncoding.problemFor("/home/zoe", "ANSI_X3.4-1968", "-i", "tick1.xml"))
                .as("ASCII names in an ASCII locale").isEmpty();
    }

    @Test
    void aCurrentFolderThatLostLettersStopsTickWithTheLocaleToStartIn() {
        assertThat(NameEncoding.problemFor("/home/" + LOST, "ANSI_X3.4-1968", "-i", "tick1.xml"))
                .hasValueSatisfying(line -> assertThat(line)
                        .as("one line naming what lost letters, the charset, and the remedy")
                        .startsWith("tick1: the current folder's name has letters that Java cannot read")
                        .contains("ANSI_X3.4-1968", "LC_ALL=C.UTF-8 ").doesNotContain("\n"));
    }

    @Test
    void aWordThatLostLettersStopsTickToo() {
        assertThat(NameEncoding.problemFor("/tmp", "ANSI_X3.4-1968", "grade", "--sphere", LOST + "/Sphere.java"))
                .hasValueSatisfying(line -> assertThat(line).startsWith("tick1: a word of the command line has"));
    }
}
