package gfx.tick1.command.render;

import gfx.tick1.engine.scene.Intersection;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Optional;
import java.util.Set;

/**
 * A quick reading of a plain render's command line, made before picocli has read it, so that the
 * scene can be loaded and rendered on other threads while picocli builds its model (which takes
 * longer than a small render). It understands only the plain forms ({@code -i FILE},
 * {@code --width=640}, the flags) and gives up on anything else. It is a guess: the render
 * command compares it with picocli's own reading, and a render started on a guess that differs
 * is thrown away, so picocli alone decides what a command line means.
 */
public final class CommandLineGuess {

    private CommandLineGuess() {
    }

    /** The options these arguments ask for, empty when they are not a plain render's. */
    public static Optional<RenderOptions> of(String... args) {
        String input = "basic_scene.xml";
        boolean strict = false;
        int width = 640, height = 480, samples = 1;
        Intersection intersection = Intersection.ROBUST;
        Integer threads = null;
        Set<String> seen = new HashSet<>();
        try {
            for (int i = 0; i < args.length; i++) {
                String arg = args[i], value = null;
                int equals = arg.indexOf('=');
                if (arg.startsWith("--") && equals > 0) {
                    value = arg.substring(equals + 1);
                    arg = arg.substring(0, equals);
                }
                String name = canonical(arg);
                if (name == null || !seen.add(name)) {
                    return Optional.empty();
                }
                boolean flag = name.equals("--strict") || name.equals("--quiet") || name.equals("--timings");
                if (flag) {
                    if (value != null) {
                        return Optional.empty();
                    }
                    strict |= name.equals("--strict");
                    continue;
                }
                if (value == null) {
                    if (i + 1 == args.length) {
                        return Optional.empty();
                    }
                    value = args[++i];
                }
                if (value.startsWith("-") && value.length() > 1) {
                    return Optional.empty();
                }
                switch (name) {
                    case "--input" -> input = value;
                    case "--width" -> width = Integer.parseInt(value);
                    case "--height" -> height = Integer.parseInt(value);
                    case "--samples" -> samples = Integer.parseInt(value);
                    case "--threads" -> threads = Integer.parseInt(value);
                    case "--intersection" -> intersection = new RenderCommand.IntersectionName().convert(value);
                    default -> { } // --output: where the image goes, not what it is
                }
            }
            // Only a file can be read twice (should the guess be wrong) with nothing lost: never a pipe.
            if (!Files.isRegularFile(Path.of(input))) {
                return Optional.empty();
            }
            return Optional.of(new RenderOptions(input, strict, width, height, samples, intersection, threads));
        } catch (RuntimeException e) {
            return Optional.empty(); // not a number, not a method, not a file name: picocli will say what is wrong
        }
    }

    /** An option's long name, or null for anything this guess does not know. */
    private static String canonical(String arg) {
        return switch (arg) {
            case "-i", "--input" -> "--input";
            case "-o", "--output" -> "--output";
            case "-q", "--quiet" -> "--quiet";
            case "--width", "--height", "--samples", "--threads", "--intersection", "--strict", "--timings" -> arg;
            default -> null;
        };
    }
}
