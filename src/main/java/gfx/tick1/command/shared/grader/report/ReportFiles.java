package gfx.tick1.command.shared.grader.report;

import gfx.tick1.engine.io.AtomicFile;
import gfx.tick1.engine.io.OwnFolder;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

/**
 * Where the report's files go, and how they are written: each file is written whole to a hidden
 * temporary file in its own folder and then renamed over the target ({@link AtomicFile}), which on
 * POSIX file systems is atomic. A grade stopped part way (Ctrl-C, a crash, a full disk) leaves the old page or the
 * new one, never half of one; at worst a {@code .NAME.RANDOM.tmp} beside it.
 */
public final class ReportFiles {

    /** The report folder's sub-folder holding one folder of feedback per student. */
    static final String FEEDBACK = "feedback";

    /**
     * The most bytes of UTF-8 in one name the report writes: NAME_MAX of Linux's usual file systems (ext4, XFS,
     * Btrfs, tmpfs), whatever the characters.
     */
    static final int MAX_NAME_BYTES = 255;

    /** The gradebook in the report folder, in the form of Moodle's grading worksheet. */
    public static final String GRADES = "grades.csv";

    /** Every student's feedback files, in the zip Moodle's "Upload multiple feedback files in a zip" reads. */
    public static final String FEEDBACK_ZIP = "feedback.zip";

    private ReportFiles() {
    }

    static void write(Path target, String text) throws IOException {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        write(target, out -> out.write(bytes));
    }

    /**
     * Writes {@code target} whole, in a folder that exists: a link at {@code target} is replaced by the file, never
     * written through ({@link AtomicFile} renames over it).
     */
    public static void write(Path target, AtomicFile.Content content) throws IOException {
        AtomicFile.write(target, content);
    }

    /**
     * {@code name} as one plain entry of a folder, the one way the report makes a name safe: a
     * separator, NUL, a C0 or C1 control character or a bidirectional formatting mark becomes a
     * space (a control would be obeyed by a terminal listing the folder, a bidi mark can make
     * one name read as another; a space, not {@code _}, since Moodle's feedback importer reads the
     * participant id after the first {@code _} of a name, and Moodle's clean_filename leaves C1
     * controls and bidi marks in a full name), and an empty name, {@code .} or {@code ..} gains a
     * leading {@code _}. Moodle's own folder names pass unchanged otherwise.
     */
    public static String plainName(String name) {
        StringBuilder out = new StringBuilder(name.length());
        for (int i = 0; i < name.length(); i++) {
            char c = name.charAt(i);
            out.append(c == '/' || c == '\\' || c < 0x20 || c >= 0x7F && c <= 0x9F || isBidiMark(c) ? ' ' : c);
        }
        String plain = out.toString();
        return plain.isEmpty() || plain.equals(".") || plain.equals("..") ? "_" + plain : plain;
    }

    /** The marks that change the direction of text: LRM, RLM, ALM and the embeddings, overrides and isolates. */
    private static boolean isBidiMark(char c) {
        return c == '\u200E' || c == '\u200F' || c == '\u061C' || c >= '\u202A' && c <= '\u202E'
                || c >= '\u2066' && c <= '\u2069';
    }

    /**
     * Whether {@code name} is one plain entry of a folder, as {@link #plainName} makes it. Only such
     * names are joined to the report folder, so nothing a submission is called can place a file,
     * or a link, outside it.
     */
    static boolean isPlainName(String name) {
        return name != null && plainName(name).equals(name);
    }

    /**
     * {@code report/feedback/<folder>}, made if need be, with neither it nor {@code report/feedback} a link ({@link
     * OwnFolder}); the folder's name must be plain (see {@link #isPlainName}).
     */
    static Path ownFeedbackFolder(Path report, String folder) throws IOException {
        Path path = feedbackFolder(report, folder);
        OwnFolder.at(path.getParent());
        return OwnFolder.at(path);
    }

    /**
     * {@code name} shortened, where need be, to {@link #MAX_NAME_BYTES} bytes of UTF-8 with {@code suffix} at its
     * end. A name of Moodle's form, {@code <full name>_<id>_<plugin part>}, keeps all from {@code _<id>_} on, and
     * loses the end of its full name: Moodle's feedback importer reads the participant from the part after the
     * first {@code _}, so feedback.zip's folder still finds the student. Any other name loses its end. A character
     * is never cut in two.
     */
    static String fitted(String name, String id, String suffix) {
        int first = name.indexOf('_');
        boolean moodles = first >= 0 && name.startsWith("_" + id + "_", first);
        String head = moodles ? name.substring(0, first) : name;
        String tail = (moodles ? name.substring(first) : "") + suffix;
        if (utf8Length(head + tail) <= MAX_NAME_BYTES) {
            return head + tail;
        }
        if (utf8Length(tail) > MAX_NAME_BYTES / 2) {
            head = name;   // not a tail worth its room: the name loses its end, the suffix is kept
            tail = suffix;
        }
        StringBuilder kept = new StringBuilder();
        int room = MAX_NAME_BYTES - utf8Length(tail);
        for (int c : head.codePoints().toArray()) {
            String character = Character.toString(c);
            room -= utf8Length(character);
            if (room < 0) {
                break;
            }
            kept.append(character);
        }
        return kept + tail;
    }

    private static int utf8Length(String text) {
        return text.getBytes(StandardCharsets.UTF_8).length;
    }

    /** {@code report/feedback/<folder>}; the folder's name must be plain (see {@link #isPlainName}). */
    public static Path feedbackFolder(Path report, String folder) {
        if (!isPlainName(folder)) {
            throw new IllegalArgumentException("a submission folder named \"" + folder
                    + "\" cannot be a folder of the report: it must be one plain name");
        }
        return report.resolve(FEEDBACK).resolve(folder);
    }
}
