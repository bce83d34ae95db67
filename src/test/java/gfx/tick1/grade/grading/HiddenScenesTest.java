package gfx.tick1.grade.grading;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A hidden scene's failure is reported without any number the student's code chose: those could
 * carry bytes of the scene it read (a PNG header's width and height hold eight of them).
 */
class HiddenScenesTest {

    private final HiddenScenes hidden = new HiddenScenes(Path.of("/nowhere"));

    @ParameterizedTest
    @CsvSource(delimiter = '|', value = {
        "the image written for this scene is unusable: the image is 2017272368 x 774976051, expected 64 x 48"
            + " | the image written for this scene is unusable: the image is not 64 x 48",
        "the program ended while rendering this scene, with exit status 120 (System.exit, or the JVM crashed)"
            + " | the program ended while rendering this scene, with an exit status of its own"
            + " (System.exit, or the JVM crashed)",
        "the program ended while rendering this scene, with exit status 0 (does the code call System.exit?)"
            + " | the program ended while rendering this scene, with an exit status of its own"
            + " (System.exit, or the JVM crashed)",
        "no image within the time limit of 10 s (an infinite loop?); the program was stopped"
            + " | no image within the time limit of 10 s (an infinite loop?); the program was stopped"})
    void numbersTheCodeChoseAreLeftOutAndTheGradersOwnKept(String reason, String reported) {
        assertThat(hidden.withoutMessages(reason)).isEqualTo(reported);
    }

    @Test
    void anExceptionKeepsItsClassAndNoFrameNorLineNumber() {
        assertThat(hidden.withoutMessages("the code threw java.lang.IllegalStateException: a message\n"
                + "    at gfx.tick1.Renderer.leakEven(Renderer.java:33)\n"
                + "    at gfx.tick1.Renderer.render(Renderer.java:9)"))
                .isEqualTo("the code threw java.lang.IllegalStateException (its message is not shown for a hidden "
                        + "scene)");
    }
}
