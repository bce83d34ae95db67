package gfx.tick1.command.shared.grader.intake;

import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Who a top-level folder of a cohort's download belongs to, read from its name.
 *
 * <p>Moodle's "Download all submissions" (mod/assign/classes/downloader.php since Moodle 4.1, the assignment's
 * download_submissions before) makes each student's prefix {@code <full name>_<participant id>} with every {@code _}
 * of the full name made a space, so the full name never holds {@code _}; with blind marking the full name is the
 * word for "Participant". From the prefix it names:
 * <ul>
 * <li>a folder {@code <prefix>_assignsubmission_file} (Moodle 4.1 and later) or {@code <prefix>_assignsubmission_file_}
 *     (before), holding the student's files;</li>
 * <li>with "Download submissions in folders" turned off, each file at the top as
 *     {@code <prefix>_assignsubmission_file_<the student's file name>}.</li>
 * </ul>
 * The participant id is therefore the number after the first {@code _}: the student's own file name, which may hold
 * {@code _<digits>_assignsubmission_file_} itself, can never choose another participant. That is also how Moodle's
 * "Upload multiple feedback files in a zip" reads a name (mod/assign/feedback/file/importziplib.php splits it at
 * {@code _} and takes the second part). The id is the number the grading worksheet shows as {@code Participant <id>}.
 *
 * @param id       the participant id, or the whole folder name when it is not Moodle's
 * @param fullName the name Moodle wrote, or the whole folder name when it is not Moodle's
 * @param moodles  whether the name is one Moodle makes, so that the id is a participant's
 */
record StudentName(String id, String fullName, boolean moodles) {

    /** A full name as Moodle writes it into a name: no {@code _}. */
    private static final String FULL_NAME = "([^_]*)";
    /**
     * A participant id as Moodle writes it: a positive whole number with no leading zero (its importer reads
     * {@code 066} as 66, so a download naming both could not be told apart).
     */
    private static final String ID = "([1-9]\\d*)";
    /** What follows the prefix in the name of every student's folder of file submissions. */
    private static final String FILE_PLUGIN = "_assignsubmission_file";

    private static final Pattern MOODLE_FOLDER = Pattern.compile(FULL_NAME + "_" + ID + FILE_PLUGIN + "_?");
    private static final Pattern MOODLE_LOOSE_FILE = Pattern.compile("(" + FULL_NAME + "_" + ID + FILE_PLUGIN
            + "_)(.+)");
    private static final Pattern OTHER_SUBMISSION_TYPE = Pattern.compile(FULL_NAME
            + "_\\d+_assignsubmission_(?!file(?:_|$))[a-z0-9]+(?:_.*)?");

    /** The student a top-level folder belongs to. */
    static StudentName ofFolder(String folder) {
        Matcher moodle = MOODLE_FOLDER.matcher(folder);
        return moodle.matches() ? new StudentName(moodle.group(2), moodle.group(1), true)
                : new StudentName(folder, folder, false);
    }

    /**
     * Moodle's folder, or loose file, of another submission type (online text, comments), which holds no Java
     * files: {@code Jane Doe_123_assignsubmission_onlinetext}, with or without a trailing {@code _}.
     */
    static boolean isOtherSubmissionType(String name) {
        return OTHER_SUBMISSION_TYPE.matcher(name).matches();
    }

    /**
     * A file at the top of a download made without folders, as the folder it would have been in and its name
     * there: {@code Jane Doe_123_assignsubmission_file_Sphere.java} is {@code Sphere.java} in {@code
     * Jane Doe_123_assignsubmission_file_}; null for any other name.
     */
    static String[] looseFileFolder(String fileName) {
        Matcher moodle = MOODLE_LOOSE_FILE.matcher(fileName);
        return moodle.matches() ? new String[] {moodle.group(1), moodle.group(4)} : null;
    }

    /**
     * The top entry of a download that holds the download rather than being one student's: no top entry is named as
     * Moodle names a student's, and this one's own entries are. {@code inside} gives each top entry's own entries'
     * names; null when no top entry holds the download.
     */
    static String holdingTheDownload(Map<String, List<String>> inside) {
        if (inside.keySet().stream().anyMatch(StudentName::moodleNamed)) {
            return null;
        }
        return inside.entrySet().stream().filter(top -> top.getValue().stream().anyMatch(StudentName::moodleNamed))
                .map(Map.Entry::getKey).findFirst().orElse(null);
    }

    private static boolean moodleNamed(String name) {
        return ofFolder(name).moodles() || looseFileFolder(name) != null;
    }
}
