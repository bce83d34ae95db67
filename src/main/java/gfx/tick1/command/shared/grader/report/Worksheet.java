package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.model.CohortInputException;
import gfx.tick1.command.shared.grader.model.StudentResult;
import gfx.tick1.engine.io.BoundedFile;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.ZonedDateTime;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * Moodle's offline grading worksheet (the assignment's "Download grading worksheet" and "Upload grading worksheet"),
 * written fresh or filled in.
 *
 * <p>What Moodle does, which this follows (mod/assign's grading table and feedback/offline importer):
 * <ul>
 * <li>The download's header is {@link #HEADER}; {@code Identifier} is {@code Participant <id>}, the same participant
 *     id Moodle puts in the folder names of "Download all submissions".</li>
 * <li>The upload finds its columns by header text, whatever their order: it needs {@code Identifier}, {@code Grade}
 *     and {@code Last modified (grade)}, and reads {@code Feedback comments} when that feedback type is on. It strips
 *     {@code Participant } from the identifier to find the student, and ignores every other column.</li>
 * <li>Grades are written with the grade item's decimals (2 by default): {@code 1.00}, {@code 0.67}; the upload reads
 *     a point as the decimal separator in any language, skips an empty grade, and skips a grade above the maximum.
 *     </li>
 * <li>The upload skips a row whose {@code Last modified (grade)} is more than a minute older than the grade Moodle
 *     holds, unless "Allow updating records that have been modified more recently in Moodle than in the
 *     spreadsheet" is ticked; so a filled worksheet keeps that cell, and a fresh one writes the grading time in
 *     Moodle's own form with the zone's offset, "Tuesday, 1 December 2026, 6:11 PM +00:00", which the upload
 *     (PHP's strtotime) reads in that zone, where a date without one would be read in the server's.</li>
 * <li>The file is UTF-8 CSV with commas; a byte-order mark is allowed.</li>
 * <li>The export writes a cell that starts as a formula would ({@code = + - @}, tab, CR) with a leading
 *     {@code '}; the feedback comments are stored as HTML.</li>
 * </ul>
 */
public final class Worksheet {

    /** The columns of a worksheet Moodle makes for an assignment with feedback comments. */
    public static final List<String> HEADER = List.of("Identifier", "Full name", "Email address", "Status", "Grade",
            "Maximum Grade", "Grade can be changed", "Last modified (submission)", "Last modified (grade)",
            "Feedback comments");

    private static final String IDENTIFIER = "Identifier", GRADE = "Grade", FEEDBACK = "Feedback comments",
            FULL_NAME = "Full name", MAXIMUM_GRADE = "Maximum Grade";
    /** How Moodle's identifier cell starts ("hiddenuser" in mod/assign's language strings). */
    private static final String PARTICIPANT = "Participant ";
    private static final String SUBMITTED = "Submitted for grading";
    /**
     * Moodle's form of a date in the worksheet, with the zone's offset added: Moodle's own download writes the
     * time in the user's zone without one, and its upload (PHP's strtotime) reads a date without an offset in
     * the server's zone, which can make a fresh grade older than Moodle's and the row skipped as stale.
     */
    private static final DateTimeFormatter MOODLE_DATE = DateTimeFormatter.ofPattern("EEEE, d MMMM yyyy, h:mm a xxx",
            Locale.ENGLISH);
    private static final String CRLF = "\r\n";
    /** The largest worksheet read: a row is some hundred bytes, and a device or an endless stream stops here. */
    private static final long MAX_BYTES = 64L << 20;
    /** Where a fresh worksheet's row has its grade, its grading time and its comment. */
    private static final int GRADE_AT = HEADER.indexOf(GRADE), GRADED_AT = HEADER.indexOf("Last modified (grade)"),
            COMMENT_AT = HEADER.indexOf(FEEDBACK);

    private final String name;
    private final byte[] bytes;
    private final List<CsvRecords.Row> rows;
    private final int identifier;
    private final int grade;
    private final int feedback;
    private final int fullName;
    private final int maximum;

    private Worksheet(String name, byte[] bytes, List<CsvRecords.Row> rows) throws CohortInputException {
        this.name = name;
        this.bytes = bytes;
        this.rows = rows;
        CsvRecords.Row header = rows.get(0);
        identifier = column(name, header, IDENTIFIER);
        grade = column(name, header, GRADE);
        feedback = column(name, header, FEEDBACK);
        fullName = header.values().indexOf(FULL_NAME);
        maximum = header.values().indexOf(MAXIMUM_GRADE);
    }

    /**
     * One student's mark, as the worksheet takes it.
     *
     * @param id       the participant id (the submission's id)
     * @param fullName the student's name, for a fresh worksheet and for messages
     * @param grade    the mark, from 0 to the maximum grade, or null to leave the Grade cell blank (Moodle's
     *                 upload skips a blank grade, so staff decide)
     * @param feedback the one-paragraph feedback for the comment cell
     */
    public record Mark(String id, String fullName, Double grade, String feedback) {

        public Mark {
            if (grade != null && (!(grade >= 0) || Double.isInfinite(grade))) {
                throw new IllegalArgumentException("a grade must be a number from 0 up, not " + grade);
            }
        }

        /** A mark with a grade. */
        public Mark(String id, String fullName, double grade, String feedback) {
            this(id, fullName, Double.valueOf(grade), feedback);
        }

        /** A result's mark: its submission's id and name, the given grade (null for blank), its reason as feedback. */
        public static Mark of(StudentResult result, Double grade) {
            return new Mark(result.submission().id(), result.submission().fullName(), grade, result.reason());
        }

        /** "Participant 42 (Jane Doe)", or the id alone where the name is the id (a folder not named by Moodle). */
        String describe() {
            return fullName.equals(id) ? id : PARTICIPANT + id + " (" + fullName + ")";
        }
    }

    /**
     * A worksheet filled in.
     *
     * @param bytes             the worksheet's bytes with the graded students' cells replaced
     * @param withoutSubmission students with a row but no submission ("Participant 12 (Jane Doe)"), in file order
     * @param withoutRow        submissions with no row, in the order given
     */
    public record Filled(byte[] bytes, List<String> withoutSubmission, List<String> withoutRow) {
    }

    /** A grade as Moodle writes it: two decimals, a point: {@code 1.00}, {@code 0.67}; blank for none. */
    public static String grade(Double grade) {
        return grade == null ? "" : BigDecimal.valueOf(grade).setScale(2, RoundingMode.HALF_UP).toPlainString();
    }

    /**
     * A fresh worksheet: {@link #HEADER}, then one row per mark in the order given, RFC 4180 quoting where a cell
     * needs it, CRLF line endings, UTF-8 without a byte-order mark (as Moodle's own download). Every cell is
     * bounded and kept from being a formula ({@link CellText#cell}); the feedback is plain text safe as HTML
     * ({@link CellText#comment}). A row whose {@code Grade} and {@code Feedback comments} are those of the same
     * participant's row in {@code earlier} keeps that row's {@code Last modified (grade)}: a grade is as old as
     * its making, so an upload of an unchanged grade never claims to be newer than a change made in Moodle since.
     * An earlier worksheet that cannot be read keeps no time.
     *
     * @param maxGrade the grade of a pass, for the {@code Maximum Grade} column
     * @param gradedAt when the grades were made, for {@code Last modified (grade)}
     * @param earlier  the worksheet an earlier grade wrote, or null
     */
    public static byte[] fresh(List<Mark> marks, double maxGrade, ZonedDateTime gradedAt, byte[] earlier) {
        Map<String, List<String>> earlierRows = new LinkedHashMap<>();
        try {
            List<CsvRecords.Row> rows = earlier == null ? List.of() : CsvRecords.read(earlier);
            if (!rows.isEmpty() && rows.get(0).values().equals(HEADER)) {
                for (CsvRecords.Row row : rows.subList(1, rows.size())) {
                    earlierRows.putIfAbsent(row.value(0), row.values());
                }
            }
        } catch (CsvRecords.Malformed e) {
            earlierRows.clear();
        }
        StringBuilder csv = new StringBuilder();
        appendRow(csv, HEADER);
        String now = MOODLE_DATE.format(gradedAt);
        for (Mark mark : marks) {
            List<String> row = row(mark, maxGrade, now);
            List<String> before = earlierRows.get(row.get(0));
            if (before != null && before.size() == HEADER.size() && before.get(GRADE_AT).equals(row.get(GRADE_AT))
                    && before.get(COMMENT_AT).equals(row.get(COMMENT_AT))) {
                row.set(GRADED_AT, before.get(GRADED_AT));
            }
            appendRow(csv, row);
        }
        return csv.toString().getBytes(StandardCharsets.UTF_8);
    }

    /** A fresh worksheet's row for {@code mark}, its cells as they are written, graded at {@code gradedAt}. */
    private static List<String> row(Mark mark, double maxGrade, String gradedAt) {
        List<String> cells = new ArrayList<>();
        for (String text : List.of(PARTICIPANT + mark.id(), mark.fullName(), "", SUBMITTED, grade(mark.grade()),
                grade(maxGrade), "Yes", "", gradedAt)) {
            cells.add(CellText.cell(text));
        }
        cells.add(CellText.comment(mark.feedback()));   // bounded and escaped as a cell already
        return cells;
    }

    private static void appendRow(StringBuilder csv, List<String> cells) {
        for (int i = 0; i < cells.size(); i++) {
            csv.append(i == 0 ? "" : ",").append(CsvRecords.encode(cells.get(i)));
        }
        csv.append(CRLF);
    }

    /**
     * Reads and checks a worksheet from disk, before anything is graded; the file itself is only read.
     *
     * @throws CohortInputException one line naming the file: not there, a folder, a zip (an .xlsx workbook is
     *                              one), not UTF-8, not CSV, or a header without the columns Moodle's upload needs
     */
    public static Worksheet read(Path worksheet) throws CohortInputException {
        if (Files.isDirectory(worksheet)) {
            throw new CohortInputException(worksheet + ": a folder, not a worksheet (--worksheet wants the CSV file "
                    + "downloaded from the assignment)");
        }
        byte[] bytes;
        try {
            bytes = BoundedFile.read(worksheet, MAX_BYTES);
        } catch (BoundedFile.TooLarge e) {
            throw new CohortInputException(worksheet + ": " + e.getMessage() + ", far more than the grading "
                    + "worksheet of any cohort");
        } catch (NoSuchFileException e) {
            throw new CohortInputException(worksheet + ": no such file");
        } catch (IOException e) {
            throw new CohortInputException(worksheet + ": cannot read the worksheet (" + e.getMessage() + ")");
        }
        return parse(worksheet.toString(), bytes);
    }

    /** A worksheet's bytes read and checked as {@link #read(Path)} does; {@code name} is for messages. */
    public static Worksheet parse(String name, byte[] worksheet) throws CohortInputException {
        if (worksheet.length >= 4 && worksheet[0] == 'P' && worksheet[1] == 'K' && worksheet[2] < 9) {
            throw new CohortInputException(name + ": a zip archive, not a worksheet: --worksheet wants the grading "
                    + "worksheet downloaded from the assignment, as CSV (an .xlsx workbook is a zip; a download of "
                    + "submissions goes to --submissions)");
        }
        List<CsvRecords.Row> rows;
        try {
            rows = CsvRecords.read(worksheet);
        } catch (CsvRecords.Malformed e) {
            throw new CohortInputException(name + ":" + e.line + ": " + e.getMessage());
        }
        if (rows.isEmpty()) {
            throw new CohortInputException(name + ":1: the worksheet is empty; download it from the assignment's "
                    + "grading page");
        }
        return new Worksheet(name, worksheet, rows);
    }

    /**
     * The assignment's maximum grade as the worksheet gives it: the {@code Maximum Grade} every student's row
     * shares, or null when there is no such column, or no row gives it as a number.
     *
     * @throws CohortInputException when two rows give different maxima
     */
    public Double maximumGrade() throws CohortInputException {
        Double found = null;
        for (CsvRecords.Row row : rows.subList(1, rows.size())) {
            Double most = maximum < 0 || !row.value(identifier).startsWith(PARTICIPANT) ? null : number(row, maximum);
            if (most != null && found != null && !most.equals(found)) {
                throw new CohortInputException(name + ":" + row.line() + ": the row's " + MAXIMUM_GRADE + " "
                        + row.value(maximum).strip() + " differs from the rows above (" + grade(found) + ")");
            }
            found = most == null ? found : most;
        }
        return found;
    }

    /**
     * The worksheet with {@code Grade} and {@code Feedback comments} filled in for each row whose identifier is
     * {@code Participant <id>} of a mark; every other byte stays as it was (other rows and columns, quoting, line
     * endings, a byte-order mark). A replaced cell keeps its quotes, and gains them where its new text needs them.
     *
     * @throws CohortInputException {@code name:line: what is wrong}: a graded row too short for its cells, or a
     *                              grade above the row's maximum
     */
    public Filled fill(List<Mark> marks) throws CohortInputException {
        Map<String, Mark> byId = new LinkedHashMap<>();
        marks.forEach(mark -> byId.putIfAbsent(mark.id(), mark));
        Set<String> matched = new HashSet<>();
        List<String> withoutSubmission = new ArrayList<>();
        ByteArrayOutputStream out = new ByteArrayOutputStream(bytes.length + 256 * marks.size());
        int copied = 0;
        for (CsvRecords.Row row : rows.subList(1, rows.size())) {
            String id = row.value(identifier);
            if (row.blank() || !id.startsWith(PARTICIPANT)) {
                continue;
            }
            Mark mark = byId.get(id.substring(PARTICIPANT.length()));
            if (mark == null) {
                String student = fullName < 0 ? "" : row.value(fullName);
                withoutSubmission.add(student.isEmpty() ? id : id + " (" + student + ")");
                continue;
            }
            matched.add(mark.id());
            if (row.cells().size() <= Math.max(grade, feedback)) {
                throw new CohortInputException(name + ":" + row.line() + ": the row has " + row.cells().size()
                        + " cells, too few for its " + GRADE + " and " + FEEDBACK + " columns");
            }
            checkWithinMaximum(row, mark);
            CsvRecords.Cell first = row.cells().get(Math.min(grade, feedback));
            CsvRecords.Cell second = row.cells().get(Math.max(grade, feedback));
            String gradeText = grade(mark.grade());
            String comment = CellText.comment(mark.feedback());
            copied = replace(out, copied, first, grade < feedback ? gradeText : comment);
            copied = replace(out, copied, second, grade < feedback ? comment : gradeText);
        }
        out.write(bytes, copied, bytes.length - copied);
        List<String> withoutRow = byId.values().stream().filter(mark -> !matched.contains(mark.id()))
                .map(Mark::describe).toList();
        return new Filled(out.toByteArray(), List.copyOf(withoutSubmission), withoutRow);
    }

    /** The cell's number, or null when it is not one (a scale, a locale's comma: Moodle checks those). */
    private static Double number(CsvRecords.Row row, int index) {
        try {
            return index < row.cells().size() ? Double.valueOf(row.value(index).strip()) : null;
        } catch (NumberFormatException e) {
            return null;
        }
    }

    /**
     * Refuses a grade above the row's {@code Maximum Grade}: Moodle would refuse it on upload, or
     * worse, take it. The usual cause is a {@code --max-grade} other than the assignment's.
     */
    private void checkWithinMaximum(CsvRecords.Row row, Mark mark) throws CohortInputException {
        Double most = maximum < 0 ? null : number(row, maximum);
        if (most != null && mark.grade() != null && mark.grade() > most) {
            String text = row.value(maximum).strip();
            throw new CohortInputException(name + ":" + row.line() + ": the grade " + grade(mark.grade())
                    + " is above the row's " + MAXIMUM_GRADE + " " + text + "; give --max-grade " + text
                    + " (the assignment's maximum)");
        }
    }

    /** Copies the bytes up to the cell, then the cell's new text; returns where copying resumes. */
    private int replace(ByteArrayOutputStream out, int copied, CsvRecords.Cell cell, String text) {
        out.write(bytes, copied, cell.start() - copied);
        String encoded = cell.quoted() ? CsvRecords.quoted(text) : CsvRecords.encode(text);
        out.writeBytes(encoded.getBytes(StandardCharsets.UTF_8));
        return cell.end();
    }

    private static int column(String name, CsvRecords.Row header, String title) throws CohortInputException {
        if (header.values().contains(title)) {
            return header.values().indexOf(title);
        }
        throw new CohortInputException(name + ":" + header.line() + ": no \"" + title + "\" column in the header; "
                + "is this the assignment's grading worksheet" + (title.equals(FEEDBACK)
                        ? ", with the feedback type \"Feedback comments\" turned on?" : ", saved with commas?"));
    }
}
