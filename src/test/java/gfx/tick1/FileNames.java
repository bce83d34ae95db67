package gfx.tick1;

import java.nio.charset.Charset;
import org.junit.jupiter.api.Assumptions;

/** What file names the JVM running the tests can hold: Java encodes them as the locale says. */
public final class FileNames {

    private FileNames() {
    }

    /** Skips the test, in one line, where file names cannot hold {@code name} (a locale that is not UTF-8). */
    public static void assumeTheyCanHold(String name) {
        String encoding = System.getProperty("sun.jnu.encoding", "UTF-8");
        Assumptions.assumeTrue(Charset.isSupported(encoding) && Charset.forName(encoding).newEncoder().canEncode(name),
                "file names here (" + encoding + ", from the locale) cannot hold \"" + name + "\"");
    }
}
