package gfx.tick1.command.bench;

import gfx.tick1.engine.math.Vector3;
import gfx.tick1.engine.render.SamplePattern;
import gfx.tick1.engine.scene.PointLight;
import gfx.tick1.engine.scene.Scene;
import gfx.tick1.engine.scene.Sphere;
import gfx.tick1.engine.scene.SphereGeometry;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

/**
 * The benchmark's yardstick for a big render: {@code scalar-tracer.c} (beside this class), a
 * plain single-threaded C tracer with tick1's maths in doubles, compiled with {@code -O3} where a
 * C compiler is on the path. The scene goes to it as a text file of exact numbers; its image
 * comes back as a PPM, to check that it traced what tick1 traces.
 */
final class ScalarC {

    static final String SOURCE = "scalar-tracer.c";
    /** The build line, as the source's own comment gives it. */
    static final List<String> FLAGS = List.of("-O3", "-ffp-contract=off");

    private final Path executable;
    private final Path sceneFile;
    private final Path image;

    private ScalarC(Path executable, Path sceneFile, Path image) {
        this.executable = executable;
        this.sceneFile = sceneFile;
        this.image = image;
    }

    /** Builds the tracer in {@code folder} for this scene and frame; throws with the reason it cannot. */
    static ScalarC build(Path folder, Scene scene, int width, int height, int samples) throws IOException {
        String compiler = compiler().orElseThrow(() -> new IOException("no C compiler (cc, gcc or clang) on the path; "
                + "Debian's is gcc (apt-get install gcc)"));
        Path source = folder.resolve(SOURCE);
        try (InputStream in = ScalarC.class.getResourceAsStream(SOURCE)) {
            Files.write(source, in.readAllBytes());
        }
        Path executable = folder.resolve("scalar-tracer");
        List<String> command = new ArrayList<>(List.of(compiler));
        command.addAll(FLAGS);
        command.addAll(List.of("-o", executable.toString(), source.toString(), "-lm"));
        run(command, "compiling " + SOURCE);
        Path sceneFile = Files.writeString(folder.resolve("scalar-tracer-scene.txt"),
                sceneText(scene, width, height, samples));
        return new ScalarC(executable, sceneFile, folder.resolve("scalar-tracer.ppm"));
    }

    /** The command a timed run is. */
    List<String> command() {
        return List.of(executable.toString(), sceneFile.toString(), image.toString());
    }

    /** The build line, for the report. */
    static String buildLine() {
        return "cc " + String.join(" ", FLAGS) + " -o scalar-tracer " + SOURCE + " -lm";
    }

    /** How many pixels of the C tracer's last image differ from {@code tick1}'s. */
    long pixelsDifferingFrom(BufferedImage tick1) throws IOException {
        byte[] ppm = Files.readAllBytes(image);
        // "P6\n<width> <height>\n255\n", then three bytes a pixel.
        int offset = 0;
        for (int newlines = 0; newlines < 3; offset++) {
            newlines += ppm[offset] == '\n' ? 1 : 0;
        }
        long differing = 0;
        for (int y = 0; y < tick1.getHeight(); y++) {
            for (int x = 0; x < tick1.getWidth(); x++) {
                int at = offset + 3 * (y * tick1.getWidth() + x);
                int rgb = (ppm[at] & 0xFF) << 16 | (ppm[at + 1] & 0xFF) << 8 | ppm[at + 2] & 0xFF;
                differing += rgb == (tick1.getRGB(x, y) & 0xFFFFFF) ? 0 : 1;
            }
        }
        return differing;
    }

    /** The scene file that scalar-tracer.c reads: every number in hexadecimal floating point, exact. */
    static String sceneText(Scene scene, int width, int height, int samples) {
        StringBuilder text = new StringBuilder(width + " " + height + " " + samples + "\n");
        // The Camera's image plane width, 2 tan(fov / 2) for its 45 degrees.
        text.append(hex(2 * Math.tan(Math.toRadians(45) / 2))).append('\n');
        SamplePattern pattern = new SamplePattern(samples);
        for (int i = 0; i < samples; i++) {
            text.append(hex(pattern.dx(i))).append(' ').append(hex(pattern.dy(i))).append('\n');
        }
        text.append(hex(scene.getAmbientLighting())).append('\n');
        PointLight light = scene.getPointLight();
        if (light == null) {
            text.append("0 0 0 0 0 0 0 0\n");
        } else {
            text.append("1 ").append(hex(light.getPosition())).append(' ').append(hex(light.getColour())).append(' ')
                    .append(hex(light.getIntensity())).append('\n');
        }
        text.append(scene.getObjects().size()).append('\n');
        for (Sphere sphere : scene.getObjects()) {
            text.append(hex(SphereGeometry.centre(sphere))).append(' ').append(hex(SphereGeometry.radius(sphere)))
                    .append(' ').append(hex(sphere.getColour())).append(' ').append(hex(sphere.getPhong_kD()))
                    .append(' ').append(hex(sphere.getPhong_kS())).append(' ').append(hex(sphere.getPhong_n()))
                    .append('\n');
        }
        return text.toString();
    }

    private static String hex(double value) {
        return Double.toHexString(value);
    }

    private static String hex(Vector3 v) {
        return hex(v.x) + " " + hex(v.y) + " " + hex(v.z);
    }

    /** The first C compiler on the path, if there is one. */
    private static Optional<String> compiler() {
        String path = System.getenv("PATH");
        for (String name : new String[] {"cc", "gcc", "clang"}) {
            for (String folder : path == null ? new String[0] : path.split(java.io.File.pathSeparator)) {
                if (!folder.isEmpty() && Files.isExecutable(Path.of(folder, name))) {
                    return Optional.of(Path.of(folder, name).toString());
                }
            }
        }
        return Optional.empty();
    }

    private static void run(List<String> command, String what) throws IOException {
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        try {
            String output = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            if (!process.waitFor(2, TimeUnit.MINUTES) || process.exitValue() != 0) {
                process.destroyForcibly();
                throw new IOException(what + " failed: " + output.strip());
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException(what + ": interrupted", e);
        }
    }
}
