package gfx.tick1.command.shared.cli;

import java.util.Optional;
import java.util.stream.Stream;

/**
 * Whether the command line's words and the current folder's name reached Java whole. Java decodes
 * them, and encodes every file name it opens, in the charset of the locale it started in
 * ({@code sun.jnu.encoding}, fixed for the life of the JVM). In a locale that is not UTF-8 on Linux
 * ({@code LANG=C}, or none set) a letter outside ASCII arrives as U+FFFD, the replacement
 * character, and a file under such a name is then "not found", or written into a new folder beside
 * it. The installed launcher starts Java in C.UTF-8 where the locale is not UTF-8; {@code java -jar}
 * cannot, so tick1 stops before it reads or writes anything, with the one line that says how to
 * start it.
 */
public final class NameEncoding {

    private static final char REPLACEMENT = '\uFFFD';

    private NameEncoding() {
    }

    /** The line to stop with when a word or the current folder's name lost letters; else empty. */
    public static Optional<String> problem(String... args) {
        return problemFor(System.getProperty("user.dir", ""), System.getProperty("sun.jnu.encoding", "?"), args);
    }

    /** As {@link #problem(String...)}, for this current folder and this charset of file names. */
    static Optional<String> problemFor(String folder, String encoding, String... args) {
        String lost = folder.indexOf(REPLACEMENT) >= 0 ? "the current folder's name"
                : Stream.of(args).anyMatch(arg -> arg.indexOf(REPLACEMENT) >= 0) ? "a word of the command line"
                : null;
        if (lost == null) {
            return Optional.empty();
        }
        return Optional.of("tick1: " + lost + " has letters that Java cannot read in this locale (its file names are "
                + encoding + "): start tick1 in a UTF-8 locale, as in LC_ALL=C.UTF-8 " + Invocation.command()
                + " ...");
    }
}
