package gfx.tick1.command.shared.grader.lookalike;

/**
 * Where the code parsed for comparing is kept between runs, by a digest of what was parsed
 * ({@link CodeReader#digest}): a cohort graded again reads each file it parsed before from here, since parsing is
 * most of what comparing costs. Called from several threads at once.
 */
public interface ParsedCodes {

    /** Keeps nothing: every file is parsed. */
    ParsedCodes NONE = new ParsedCodes() {
        @Override
        public ParsedCode get(String digest) {
            return null;
        }

        @Override
        public void put(String digest, ParsedCode code) {
            // nothing kept
        }
    };

    /** The code kept under {@code digest}, or null when none is (or what is kept cannot be read). */
    ParsedCode get(String digest);

    /** Keeps {@code code} under {@code digest}; one that cannot be kept is parsed again next time. */
    void put(String digest, ParsedCode code);
}
