package gfx.tick1.engine.image;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** An image handed to the PNG writer while its rows are still being drawn. */
class RowByRowImageTest {

    private static BufferedImage noise(int width, int height) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Random random = new Random(7);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                image.setRGB(x, y, random.nextInt(1 << 24) & (x * y % 7 == 0 ? 0xFFFFFF : 0x3F3F3F));
            }
        }
        return image;
    }

    @Test
    void encodesToTheSameBytesAsTheFinishedImageWhileRowsArriveInAnyOrder() throws Exception {
        BufferedImage finished = noise(97, 61);
        ByteArrayOutputStream expected = new ByteArrayOutputStream();
        PngOutput.write(finished, expected);

        BufferedImage drawing = new BufferedImage(97, 61, BufferedImage.TYPE_INT_RGB);
        RowByRowImage streamed = new RowByRowImage(drawing);
        List<Integer> rows = new ArrayList<>();
        for (int y = 0; y < 61; y++) {
            rows.add(y);
        }
        Collections.shuffle(rows, new Random(3));
        Thread painter = new Thread(() -> {
            for (int y : rows) {
                for (int x = 0; x < 97; x++) {
                    drawing.setRGB(x, y, finished.getRGB(x, y));
                }
                streamed.rowDone(y);
            }
        });
        painter.start();
        ByteArrayOutputStream actual = new ByteArrayOutputStream();
        PngOutput.write(streamed, actual);
        painter.join();
        assertThat(actual.toByteArray()).isEqualTo(expected.toByteArray());
    }

    @Test
    void aReaderWaitingForRowsThatWillNeverComeIsToldWhy() {
        RowByRowImage streamed = new RowByRowImage(new BufferedImage(8, 8, BufferedImage.TYPE_INT_RGB));
        streamed.rowDone(0);
        streamed.abandon("the render failed");
        assertThatThrownBy(() -> PngOutput.write(streamed, new ByteArrayOutputStream()))
                .isInstanceOfAny(IllegalStateException.class, IOException.class)
                .hasStackTraceContaining("the render failed");
    }
}
