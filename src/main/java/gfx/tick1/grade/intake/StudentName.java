package gfx.tick1.grade.intake;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Who a top-level folder of a cohort's download belongs to, read from its name.
 *
 * <p>Moodle's "Download all submissions" names each student's folder {@code <full name>_<participant id>_
 * assignsubmission_file_} (mod/assign's download_submissions: the name has its underscores made spaces, but a
 * folder renamed by hand may keep some, so the id is read from the right). With "Download submissions in folders"
 * turned off, Moodle writes each file at the top instead, as {@code <full name>_<id>_assignsubmission_file_<file>}.
 * The participant id is the number Moodle's grading worksheet shows as {@code Participant <id>}.
 *
 * @param id       the participant id, or the whole folder name when it is not Moodle's
 * @param fullName the name Moodle wrote, or the whole folder name when it is not Moodle's
 */
record StudentName(String id, String fullName) {

    /** What Moodle appends to the name and id of every student's folder of file submissions. */
    static final String MOODLE_SUFFIX = "_assignsubmission_file_";

    private static final Pattern MOODLE_FOLDER = Pattern.compile("(.*)_(\\d+)" + MOODLE_SUFFIX);
    private static final Pattern MOODLE_LOOSE_FILE = Pattern.compile("((.*)_(\\d+)" + MOODLE_SUFFIX + ")(.+)");
    private static final Pattern OTHER_SUBMISSION_TYPE =
            Pattern.compile(".*_\\d+_assignsubmission_(?!file_)[a-z]+_.*");

    /** The student a top-level folder belongs to. */
    static StudentName ofFolder(String folder) {
        Matcher moodle = MOODLE_FOLDER.matcher(folder);
        return moodle.matches() ? new StudentName(moodle.group(2), moodle.group(1)) : new StudentName(folder, folder);
    }

    /**
     * Moodle's folder, or loose file, of another submission type (online text, comments), which holds no Java
     * files: {@code Jane Doe_123_assignsubmission_onlinetext_}.
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
}
