package gfx.tick1.grade.report;

import gfx.tick1.grade.model.CohortInputException;
import gfx.tick1.grade.model.StudentResult;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
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
 *     Moodle's own form, "Tuesday, 1 December 2026, 6:11 PM", which the upload reads back.</li>
 * <li>The file is UTF-8 CSV with commas; a byte-order mark is allowed.</li>
 * </ul>
 */
public final class Worksheet {

    /** The columns of a worksheet Moodle makes for an assignment with feedback comments. */
    public static final List<String> HEADER = List.of("Identifier", "Full name", "Email address", "Status", "Grade",
            "Maximum Grade", "Grade can be changed", "Last modified (submission)", "Last modified (grade)",
            "Feedback comments");

    private static final String IDENTIFIER = "Identifier";
    private static final String GRADE = "Grade";
    private static final String FEEDBACK = "Feedback comments";
    private static final String FULL_NAME = "Full name";
    private static final String MAXIMUM_GRADE = "Maximum Grade";
    /** How Moodle's identifier cell starts ("hiddenuser" in mod/assign's language strings). */
    private static final String PARTICIPANT = "Participant ";
    private static final String SUBMITTED = "Submitted for grading";
    private static final DateTimeFormatter MOODLE_DATE = DateTimeFormatter.ofPattern("EEEE, d MMMM yyyy, h:mm a",
            Locale.ENGLISH);
    private static final String CRLF = "\r\n";

    private Worksheet() {
    }

    /**
     * One student's mark, as the worksheet takes it.
     *
     * @param id       the participant id (the submission's id)
     * @param fullName the student's name, for a fresh worksheet and for messages
     * @param grade    the mark, from 0 to the maximum grade
     * @param feedback the one-paragraph feedback for the comment cell
     */
    public record Mark(String id, String fullName, double grade, String feedback) {

        public Mark {
            if (!(grade >= 0) || Double.isInfinite(grade)) {
                throw new IllegalArgumentException("a grade must be a number from 0 up, not " + grade);
            }
        }

        /** A result's mark: its submission's id and name, the given grade, and its reason as the feedback. */
        public static Mark of(StudentResult result, double grade) {
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

    /** A grade as Moodle writes it: two decimals, a point: {@code 1.00}, {@code 0.67}. */
    public static String grade(double grade) {
        return BigDecimal.valueOf(grade).setScale(2, RoundingMode.HALF_UP).toPlainString();
    }

    /**
     * A fresh worksheet: {@link #HEADER}, then one row per mark in the order given, RFC 4180 quoting where a cell
     * needs it, CRLF line endings, UTF-8 without a byte-order mark (as Moodle's own download).
     *
     * @param maxGrade the grade of a pass, for the {@code Maximum Grade} column
     * @param gradedAt when the grades were made, for {@code Last modified (grade)}
     */
    public static byte[] fresh(List<Mark> marks, double maxGrade, ZonedDateTime gradedAt) {
        StringBuilder csv = new StringBuilder();
        appendRow(csv, HEADER);
        for (Mark mark : marks) {
            appendRow(csv, List.of(PARTICIPANT + mark.id(), mark.fullName(), "", SUBMITTED, grade(mark.grade()),
                    grade(maxGrade), "Yes", "", MOODLE_DATE.format(gradedAt), mark.feedback()));
        }
        return csv.toString().getBytes(StandardCharsets.UTF_8);
    }

    private static void appendRow(StringBuilder csv, List<String> cells) {
        for (int i = 0; i < cells.size(); i++) {
            csv.append(i == 0 ? "" : ",").append(CsvRecords.encode(cells.get(i), false));
        }
        csv.append(CRLF);
    }

    /** {@link #fill(String, byte[], List)} of a worksheet read from disk; the file itself is left as it is. */
    public static Filled fill(Path worksheet, List<Mark> marks) throws IOException {
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(worksheet);
        } catch (IOException e) {
            throw new CohortInputException(worksheet + ": cannot read the worksheet (" + e.getMessage() + ")");
        }
        return fill(worksheet.toString(), bytes, marks);
    }

    /**
     * The worksheet with {@code Grade} and {@code Feedback comments} filled in for each row whose identifier is
     * {@code Participant <id>} of a mark; every other byte stays as it was (other rows and columns, quoting, line
     * endings, a byte-order mark). A replaced cell keeps its quotes, and gains them where its new text needs them.
     *
     * @param name the worksheet's name, for messages
     * @throws CohortInputException {@code name:line: what is wrong}: not UTF-8, not CSV (a quote never closed), or a
     *                              header without {@code Identifier}, {@code Grade} or {@code Feedback comments}
     */
    public static Filled fill(String name, byte[] worksheet, List<Mark> marks) throws CohortInputException {
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
        CsvRecords.Row header = rows.get(0);
        int identifier = column(name, header, IDENTIFIER);
        int grade = column(name, header, GRADE);
        int feedback = column(name, header, FEEDBACK);
        int fullName = header.cells().stream().map(CsvRecords.Cell::value).toList().indexOf(FULL_NAME);
        int maximum = header.cells().stream().map(CsvRecords.Cell::value).toList().indexOf(MAXIMUM_GRADE);
        Map<String, Mark> byId = new LinkedHashMap<>();
        marks.forEach(mark -> byId.putIfAbsent(mark.id(), mark));
        Set<String> matched = new HashSet<>();
        List<String> withoutSubmission = new ArrayList<>();
        ByteArrayOutputStream out = new ByteArrayOutputStream(worksheet.length + 256 * marks.size());
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
            checkWithinMaximum(name, row, maximum, mark);
            CsvRecords.Cell first = row.cells().get(Math.min(grade, feedback));
            CsvRecords.Cell second = row.cells().get(Math.max(grade, feedback));
            String firstText = grade < feedback ? grade(mark.grade()) : mark.feedback();
            String secondText = grade < feedback ? mark.feedback() : grade(mark.grade());
            copied = replace(worksheet, out, copied, first, firstText);
            copied = replace(worksheet, out, copied, second, secondText);
        }
        out.write(worksheet, copied, worksheet.length - copied);
        List<String> withoutRow = byId.values().stream().filter(mark -> !matched.contains(mark.id()))
                .map(Mark::describe).toList();
        return new Filled(out.toByteArray(), List.copyOf(withoutSubmission), withoutRow);
    }

    /**
     * Refuses a grade above the row's {@code Maximum Grade}: Moodle would refuse it on upload, or
     * worse, take it. The usual cause is a {@code --max-grade} other than the assignment's.
     */
    private static void checkWithinMaximum(String name, CsvRecords.Row row, int maximum, Mark mark)
            throws CohortInputException {
        if (maximum < 0 || maximum >= row.cells().size()) {
            return;
        }
        String text = row.value(maximum).strip();
        double most;
        try {
            most = Double.parseDouble(text);
        } catch (NumberFormatException e) {
            return;   // a maximum written in a form of its own (a scale, a locale's comma): Moodle checks it
        }
        if (mark.grade() > most) {
            throw new CohortInputException(name + ":" + row.line() + ": the grade " + grade(mark.grade())
                    + " is above the row's " + MAXIMUM_GRADE + " " + text + "; give --max-grade " + text
                    + " (the assignment's maximum)");
        }
    }

    /** Copies the bytes up to the cell, then the cell's new text; returns where copying resumes. */
    private static int replace(byte[] worksheet, ByteArrayOutputStream out, int copied, CsvRecords.Cell cell,
            String text) {
        out.write(worksheet, copied, cell.start() - copied);
        out.writeBytes(CsvRecords.encode(text, cell.quoted()).getBytes(StandardCharsets.UTF_8));
        return cell.end();
    }

    private static int column(String name, CsvRecords.Row header, String title) throws CohortInputException {
        for (int i = 0; i < header.cells().size(); i++) {
            if (header.cells().get(i).value().equals(title)) {
                return i;
            }
        }
        throw new CohortInputException(name + ":" + header.line() + ": no \"" + title + "\" column in the header; "
                + "is this the assignment's grading worksheet" + (title.equals(FEEDBACK)
                        ? ", with the feedback type \"Feedback comments\" turned on?" : ", saved with commas?"));
    }
}
