package gfx.tick1.command.grade;

/**
 * Names exactly as Moodle makes and reads them, written down from Moodle's own source, so that tests of the
 * intake and of feedback.zip use no name Moodle could not make.
 *
 * <p>Making (mod/assign/classes/downloader.php, Moodle 4.1 and later; mod/assign/locallib.php's
 * download_submissions before):
 * <ul>
 * <li>the prefix is {@code clean_filename(str_replace('_', ' ', $fullname) . '_' . $uniqueid)} (before 4.1 with a
 *     further {@code '_'} inside the clean_filename); with blind marking the full name is
 *     {@code get_string('participant', 'mod_assign')}, "Participant" in English;</li>
 * <li>a folder is {@code clean_filename($prefix . '_' . $subtype . '_' . $type)}, for a file submission
 *     {@code ..._assignsubmission_file} (before 4.1 {@code $prefix . $subtype . '_' . $type . '_'}, ending in
 *     {@code _});</li>
 * <li>without folders, a file is {@code clean_filename($prefix . '_' . $subtype . '_' . $type . '_' .
 *     $zipfilename)}, the student's file name as they uploaded it.</li>
 * </ul>
 * {@code clean_filename($s)} is {@code clean_param($s, PARAM_FILE)} (lib/moodlelib.php, Moodle 4.x): it deletes
 * control characters and {@code & < > " ` | ' : \ /}, and makes {@code .} or {@code ..} empty.
 *
 * <p>Reading (mod/assign/feedback/file/importziplib.php, is_valid_filename_for_import, Moodle 4.1 and later): each
 * element of a path in the uploaded zip is split as {@code explode('_', $pathpart, 5)}; an element of at least four
 * parts whose second is numeric and a participant's id, and whose third and fourth name a plugin, gives the
 * participant ("fullname_userid_plugintype_pluginname as created by zip export in Moodle >= 4.1 resp.
 * fullname_userid_plugintype_pluginname_ as created by earlier versions").
 */
public final class MoodleNaming {

    /** The full name Moodle writes for every student of an assignment with blind marking (English). */
    public static final String PARTICIPANT = "Participant";

    private MoodleNaming() {
    }

    /** Moodle's clean_filename: clean_param PARAM_FILE. */
    public static String cleanFilename(String name) {
        StringBuilder out = new StringBuilder();
        name.codePoints().filter(c -> c >= 0x20 && c != 0x7F && "&<>\"`|':\\/".indexOf(c) < 0)
                .forEach(out::appendCodePoint);
        String clean = out.toString();
        return clean.equals(".") || clean.equals("..") ? "" : clean;
    }

    /** The prefix of Moodle 4.1 and later. */
    public static String prefix(String fullName, long id) {
        return cleanFilename(fullName.replace('_', ' ') + "_" + id);
    }

    /** A student's folder in a download of Moodle 4.1 or later: no trailing {@code _}. */
    public static String folder(String fullName, long id) {
        return cleanFilename(prefix(fullName, id) + "_assignsubmission_file");
    }

    /** A student's folder in a download of Moodle 3.1 to 4.0: a trailing {@code _}. */
    public static String folderBefore41(String fullName, long id) {
        return cleanFilename(cleanFilename(fullName.replace('_', ' ') + "_" + id + "_") + "assignsubmission_file_");
    }

    /** A student's file at the top of a download made without folders. */
    public static String looseFile(String fullName, long id, String uploadedName) {
        return cleanFilename(prefix(fullName, id) + "_assignsubmission_file_" + uploadedName);
    }

    /**
     * The participant id Moodle's feedback importer takes from a path of the uploaded zip, or -1 for none: the
     * first element that splits into at least four parts with a number second and {@code assignsubmission} or
     * {@code assignfeedback} third (a plugin type; the fourth part must name one of its plugins, here {@code file}).
     */
    public static long importerParticipant(String path) {
        for (String part : path.split("/", -1)) {
            String[] info = part.split("_", 5);
            if (info.length < 4 || !info[1].matches("\\d+")) {
                continue;
            }
            if (info[2].matches("assign(submission|feedback)") && info[3].equals("file")) {
                return Long.parseLong(info[1]);
            }
        }
        return -1;
    }
}
