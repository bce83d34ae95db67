package gfx.tick1.engine.image;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.Transparency;
import java.awt.color.ColorSpace;
import java.awt.color.ICC_ColorSpace;
import java.awt.color.ICC_Profile;
import java.awt.image.BufferedImage;
import java.awt.image.ComponentColorModel;
import java.awt.image.DataBuffer;
import java.awt.image.DataBufferByte;
import java.awt.image.Raster;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/** {@link RgbPixels} gives what getRGB gives, top byte cleared, whatever the image's kind. */
class RgbPixelsTest {

    /** getRGB's answer with its top byte cleared: the definition RgbPixels must meet. */
    private static int[] byGetRgb(BufferedImage image) {
        int[] rgb = image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] &= 0xFFFFFF;
        }
        return rgb;
    }

    /** An image of {@code type} with every channel (alpha too, where there is one) at random. */
    private static BufferedImage random(int type, int width, int height) {
        BufferedImage image = new BufferedImage(width, height, type);
        Random random = new Random(type * 31L + width);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                image.setRGB(x, y, random.nextInt());
            }
        }
        return image;
    }

    @ParameterizedTest(name = "type {0}")
    @ValueSource(ints = {BufferedImage.TYPE_INT_RGB, BufferedImage.TYPE_INT_ARGB, BufferedImage.TYPE_INT_ARGB_PRE,
        BufferedImage.TYPE_INT_BGR, BufferedImage.TYPE_3BYTE_BGR, BufferedImage.TYPE_4BYTE_ABGR,
        BufferedImage.TYPE_4BYTE_ABGR_PRE, BufferedImage.TYPE_USHORT_565_RGB, BufferedImage.TYPE_BYTE_GRAY,
        BufferedImage.TYPE_USHORT_GRAY, BufferedImage.TYPE_BYTE_INDEXED})
    void anImageOfEachTypeGivesGetRgbsColours(int type) {
        BufferedImage image = random(type, 37, 23);
        assertThat(RgbPixels.of(image)).as("type %d", type).isEqualTo(byGetRgb(image));
    }

    @ParameterizedTest(name = "type {0}")
    @ValueSource(ints = {BufferedImage.TYPE_INT_RGB, BufferedImage.TYPE_3BYTE_BGR, BufferedImage.TYPE_4BYTE_ABGR})
    void aSubimageGivesItsOwnColoursNotItsParentsFirstRows(int type) {
        BufferedImage inner = random(type, 41, 29).getSubimage(3, 5, 30, 20);
        assertThat(RgbPixels.of(inner)).as("type %d, inside a border", type).isEqualTo(byGetRgb(inner));
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"linear RGB", "CIE XYZ"})
    void anImageInAnotherColourSpaceIsConvertedAsGetRgbConvertsIt(String name) {
        ColorSpace space = ColorSpace.getInstance(name.equals("linear RGB") ? ColorSpace.CS_LINEAR_RGB
                : ColorSpace.CS_CIEXYZ);
        ComponentColorModel model = new ComponentColorModel(space, false, false, Transparency.OPAQUE,
                DataBuffer.TYPE_BYTE);
        BufferedImage image = new BufferedImage(model, Raster.createInterleavedRaster(DataBuffer.TYPE_BYTE, 17, 13,
                17 * 3, 3, new int[] {2, 1, 0}, null), false, null);
        byte[] samples = ((DataBufferByte) image.getRaster().getDataBuffer()).getData();
        new Random(7).nextBytes(samples);
        assertThat(RgbPixels.of(image)).as(name).isEqualTo(byGetRgb(image));
    }

    /** coerceData(true) premultiplies the colours but leaves the type INT_ARGB or 4BYTE_ABGR. */
    @ParameterizedTest(name = "type {0}")
    @ValueSource(ints = {BufferedImage.TYPE_INT_ARGB, BufferedImage.TYPE_4BYTE_ABGR})
    void anImageCoercedToPremultipliedAlphaGivesGetRgbsColours(int type) {
        BufferedImage image = random(type, 37, 23);
        image.coerceData(true);
        assertThat(image.getType()).as("the type after coerceData").isEqualTo(type);
        assertThat(RgbPixels.of(image)).as("type %d, premultiplied", type).isEqualTo(byGetRgb(image));
    }

    /** A colour space that says it is sRGB but is not sRGB's own instance: getRGB converts through it. */
    @Test
    void aColourSpaceThatOnlyClaimsToBeSrgbIsConvertedAsGetRgbConvertsIt() {
        ColorSpace claims = new ICC_ColorSpace(ICC_Profile.getInstance(ColorSpace.CS_LINEAR_RGB)) {
            @Override
            public boolean isCS_sRGB() {
                return true;
            }
        };
        ComponentColorModel model = new ComponentColorModel(claims, false, false, Transparency.OPAQUE,
                DataBuffer.TYPE_BYTE);
        BufferedImage image = new BufferedImage(model, Raster.createInterleavedRaster(DataBuffer.TYPE_BYTE, 17, 13,
                17 * 3, 3, new int[] {2, 1, 0}, null), false, null);
        new Random(7).nextBytes(((DataBufferByte) image.getRaster().getDataBuffer()).getData());
        assertThat(image.getType()).as("the type").isEqualTo(BufferedImage.TYPE_3BYTE_BGR);
        assertThat(RgbPixels.of(image)).as("linear RGB that claims to be sRGB").isEqualTo(byGetRgb(image));
    }

    static Stream<Path> referenceImages() throws IOException {
        try (Stream<Path> files = Files.list(Path.of("reference-images"))) {
            return files.filter(file -> file.toString().endsWith(".png")).sorted().toList().stream();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("referenceImages")
    void aPngAsImageIoReadsItGivesGetRgbsColours(Path png) throws IOException {
        BufferedImage image = ImageIO.read(png.toFile());
        assertThat(RgbPixels.of(image)).as("%s (type %d)", png, image.getType()).isEqualTo(byGetRgb(image));
    }

    /** PNGs of the kinds a student's program may write: with alpha, grey, with a palette. */
    static List<Integer> writtenTypes() {
        return List.of(BufferedImage.TYPE_INT_ARGB, BufferedImage.TYPE_BYTE_GRAY, BufferedImage.TYPE_BYTE_INDEXED,
                BufferedImage.TYPE_USHORT_GRAY, BufferedImage.TYPE_INT_RGB);
    }

    @ParameterizedTest(name = "written from type {0}")
    @MethodSource("writtenTypes")
    void aPngOfAnyKindReadBackGivesGetRgbsColours(int type) throws IOException {
        ByteArrayOutputStream png = new ByteArrayOutputStream();
        ImageIO.write(random(type, 19, 11), "png", png);
        BufferedImage image = ImageIO.read(new ByteArrayInputStream(png.toByteArray()));
        assertThat(RgbPixels.of(image)).as("read back as type %d", image.getType()).isEqualTo(byGetRgb(image));
    }
}
