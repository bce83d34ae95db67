package gfx.tick1.command.shared.grader.report;

import gfx.tick1.command.shared.grader.model.CohortInputException;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.time.ZoneId;
import java.time.ZonedDateTime;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class WorksheetTest {

    private static final String HEADER = "Identifier,Full name,Email address,Status,Grade,Maximum Grade,"
            + "Grade can be changed,Last modified (submission),Last modified (grade),Feedback comments,Department";

    /** A worksheet as Moodle downloads it, with a column of the course's own, in CRLF lines. */
    private static String worksheet(String grade101, String feedback101, String grade103, String feedback103) {
        return HEADER + "\r\n"
                + "Participant 101,Zoë Ünal,zoe@example.org,Submitted for grading," + grade101 + ",1.00,Yes,"
                + "\"Monday, 30 November 2026, 9:00 AM\",-," + feedback101 + ",Computer Lab\r\n"
                + "Participant 102,\"Smith, John\",john@example.org,No submission,,1.00,Yes,-,-,"
                + "\"Said \"\"hi\"\"\r\nthen left\",Physics\r\n"
                + "\"Participant 103\",Ana Øberg,ana@example.org,Submitted for grading," + grade103 + ",1.00,Yes,-,-,"
                + feedback103 + ",\"Maths, Applied\"\r\n";
    }

    private static final List<Worksheet.Mark> MARKS = List.of(
            new Worksheet.Mark("101", "Zoë Ünal", 1, "Passed, every scene matched."),
            new Worksheet.Mark("103", "Ana Øberg", 0, "tick1.xml differs: \"R.V not clamped\"."),
            new Worksheet.Mark("999", "Nobody Known", 0, "no Sphere.java in the submission"));

    private static byte[] utf8(String text) {
        return text.getBytes(StandardCharsets.UTF_8);
    }

    @Test
    void aFilledWorksheetIsTheInputWithOnlyTheGradedCellsReplaced() throws Exception {
        byte[] input = utf8(worksheet("", "", "\"\"", "\"\""));

        Worksheet.Filled filled = Worksheet.parse("grades.csv", input).fill(MARKS);

        assertThat(new String(filled.bytes(), StandardCharsets.UTF_8)).isEqualTo(worksheet("1.00",
                "\"Passed, every scene matched.\"", "\"0.00\"", "\"tick1.xml differs: \"\"R.V not clamped\"\".\""));
    }

    @Test
    void parsingAFilledWorksheetGivesTheInputsCellsBesideTheFilledOnes() throws Exception {
        byte[] input = utf8(worksheet("", "", "\"\"", "\"\""));

        byte[] output = Worksheet.parse("grades.csv", input).fill(MARKS).bytes();

        List<List<String>> before = cells(input);
        List<List<String>> after = cells(output);
        assertThat(after).hasSameSizeAs(before);
        for (int row = 0; row < before.size(); row++) {
            for (int column = 0; column < before.get(row).size(); column++) {
                boolean filled = (row == 1 || row == 3) && (column == 4 || column == 9);
                if (!filled) {
                    assertThat(after.get(row).get(column)).as("row %d, column %d", row, column)
                            .isEqualTo(before.get(row).get(column));
                }
            }
        }
        assertThat(after.get(3).get(9)).isEqualTo("tick1.xml differs: \"R.V not clamped\".");
    }

    private static List<List<String>> cells(byte[] csv) throws CsvRecords.Malformed {
        List<List<String>> rows = new ArrayList<>();
        for (CsvRecords.Row row : CsvRecords.read(csv)) {
            rows.add(row.cells().stream().map(CsvRecords.Cell::value).toList());
        }
        return rows;
    }

    @Test
    void studentsWithoutASubmissionAndSubmissionsWithoutARowAreListed() throws Exception {
        Worksheet.Filled filled = Worksheet.parse("grades.csv", utf8(worksheet("", "", "", ""))).fill(MARKS);

        assertThat(filled.withoutSubmission()).containsExactly("Participant 102 (Smith, John)");
        assertThat(filled.withoutRow()).containsExactly("Participant 999 (Nobody Known)");
    }

    @Test
    void columnsAreFoundByNameAndTheByteOrderMarkAndMixedLineEndingsStay() throws Exception {
        String input = "\uFEFFFeedback comments,Grade,Identifier\n"
                + "old,0.50,Participant 7\r\n"
                + ",,Participant 8\r"
                + "x,y,z";

        byte[] output = Worksheet.parse("w.csv", utf8(input)).fill(List.of(new Worksheet.Mark("7", "A", 1, "ok"),
                new Worksheet.Mark("8", "B", 0.6667, "close"))).bytes();

        assertThat(new String(output, StandardCharsets.UTF_8)).isEqualTo("\uFEFFFeedback comments,Grade,Identifier\n"
                + "ok,1.00,Participant 7\r\n"
                + "close,0.67,Participant 8\r"
                + "x,y,z");
    }

    @Test
    void aFreshWorksheetHasMoodlesColumnsAndQuotesOnlyWhereACellNeedsIt() {
        ZonedDateTime gradedAt = ZonedDateTime.of(2026, 12, 1, 18, 11, 0, 0, ZoneId.of("Europe/London"));

        byte[] csv = Worksheet.fresh(List.of(new Worksheet.Mark("42", "Zoë Ünal", 1, "Passed."),
                new Worksheet.Mark("43", "Smith, John", 0, "It said \"hi\",\nthen stopped.")), 1, gradedAt, null);

        assertThat(new String(csv, StandardCharsets.UTF_8)).isEqualTo("Identifier,Full name,Email address,Status,"
                + "Grade,Maximum Grade,Grade can be changed,Last modified (submission),Last modified (grade),"
                + "Feedback comments\r\n"
                + "Participant 42,Zoë Ünal,,Submitted for grading,1.00,1.00,Yes,,"
                + "\"Tuesday, 1 December 2026, 6:11 PM +00:00\",Passed.\r\n"
                + "Participant 43,\"Smith, John\",,Submitted for grading,0.00,1.00,Yes,,"
                + "\"Tuesday, 1 December 2026, 6:11 PM +00:00\",\"It said \"\"hi\"\", then stopped.\"\r\n");
    }

    @Test
    void aRowWhoseGradeDidNotChangeKeepsItsLastModifiedGrade() throws Exception {
        ZonedDateTime first = ZonedDateTime.of(2026, 12, 1, 18, 11, 0, 0, ZoneId.of("UTC"));
        ZonedDateTime second = first.plusDays(1);
        byte[] earlier = Worksheet.fresh(List.of(new Worksheet.Mark("42", "Ann", 1, "Passed."),
                new Worksheet.Mark("43", "Bob", 0, "Failed.")), 1, first, null);

        byte[] again = Worksheet.fresh(List.of(new Worksheet.Mark("42", "Ann", 1, "Passed."),
                new Worksheet.Mark("43", "Bob", 1, "Passed."), new Worksheet.Mark("44", "Cy", 1, "Passed.")), 1,
                second, earlier);

        List<CsvRecords.Row> rows = CsvRecords.read(again);
        int column = Worksheet.HEADER.indexOf("Last modified (grade)");
        assertThat(rows.subList(1, 4)).extracting(row -> row.value(column)).as("Last modified (grade) of 42 "
                + "(unchanged), 43 (its grade changed) and 44 (new)").containsExactly(
                        "Tuesday, 1 December 2026, 6:11 PM +00:00", "Wednesday, 2 December 2026, 6:11 PM +00:00",
                        "Wednesday, 2 December 2026, 6:11 PM +00:00");
    }

    @Test
    void anEarlierWorksheetThatCannotBeReadKeepsNoTime() {
        ZonedDateTime now = ZonedDateTime.of(2026, 12, 2, 18, 11, 0, 0, ZoneId.of("UTC"));

        byte[] fresh = Worksheet.fresh(MARKS, 1, now, "\"never closed".getBytes(StandardCharsets.UTF_8));

        assertThat(fresh).isEqualTo(Worksheet.fresh(MARKS, 1, now, null));
    }

    @Test
    void aFreshWorksheetIsOneAFillReadsBack() throws Exception {
        byte[] fresh = Worksheet.fresh(MARKS, 1, ZonedDateTime.of(2026, 1, 2, 3, 4, 5, 0, ZoneId.of("UTC")), null);

        Worksheet.Filled again = Worksheet.parse("grades.csv", fresh).fill(MARKS);

        assertThat(again.bytes()).isEqualTo(fresh);
        assertThat(again.withoutRow()).isEmpty();
        assertThat(again.withoutSubmission()).isEmpty();
    }

    @Test
    void gradesHaveTwoDecimalsAndAPoint() {
        assertThat(List.of(1.0, 0.0, 2.0 / 3, 0.125, 100.0)).extracting(Worksheet::grade)
                .containsExactly("1.00", "0.00", "0.67", "0.13", "100.00");
    }

    @Test
    void aQuoteNeverClosedIsOneLineWithTheLineItOpensOn() {
        String input = HEADER + "\r\nParticipant 1,A,,,,,,,,ok,x\r\nParticipant 2,\"B\r\nno end";

        assertThatThrownBy(() -> Worksheet.parse("w.csv", utf8(input)).fill(MARKS))
                .isInstanceOf(CohortInputException.class)
                .hasMessage("w.csv:3: a quoted cell is never closed (a \" with no closing \")");
    }

    @Test
    void textAfterAClosingQuoteIsMalformed() {
        String input = HEADER + "\n\"Participant 1\"x,A\n";

        assertThatThrownBy(() -> Worksheet.parse("w.csv", utf8(input)).fill(MARKS))
                .hasMessage("w.csv:2: text after a closing quote in a cell (a quote inside a quoted cell is written "
                        + "\"\")");
    }

    @Test
    void aHeaderWithoutTheFeedbackColumnIsOneLine() {
        assertThatThrownBy(() -> Worksheet.parse("w.csv", utf8("Identifier,Grade\r\n")).fill(MARKS))
                .hasMessage("w.csv:1: no \"Feedback comments\" column in the header; is this the assignment's grading "
                        + "worksheet, with the feedback type \"Feedback comments\" turned on?");
    }

    @Test
    void aHeaderWithoutTheIdentifierColumnIsOneLine() {
        assertThatThrownBy(() -> Worksheet.parse("w.csv", utf8("Identifier;Grade;Feedback comments\r\n"))
                .fill(MARKS))
                .hasMessage("w.csv:1: no \"Identifier\" column in the header; is this the assignment's grading "
                        + "worksheet, saved with commas?");
    }

    @Test
    void aWorksheetThatIsNotUtf8IsOneLineWithTheLine() {
        byte[] input = (HEADER + "\r\nParticipant 1,Zo\u00eb,,,,,,,,,\r\n").getBytes(StandardCharsets.ISO_8859_1);

        assertThatThrownBy(() -> Worksheet.parse("w.csv", input).fill(MARKS))
                .hasMessage("w.csv:2: byte 0xEB is not UTF-8 (save the worksheet as \"CSV UTF-8\")");
    }

    @Test
    void aGradeAboveTheRowsMaximumIsRefusedInOneLine() {
        String input = HEADER + "\r\nParticipant 101,Zoë Ünal,,Submitted for grading,,1.00,Yes,,,,Maths\r\n";
        assertThatThrownBy(() -> Worksheet.parse("w.csv", utf8(input)).fill(
                List.of(new Worksheet.Mark("101", "Zoë Ünal", 10, "Passed."))))
                .hasMessage("w.csv:2: the grade 10.00 is above the row's Maximum Grade 1.00; give --max-grade 1.00 "
                        + "(the assignment's maximum)");
    }

    @Test
    void aGradedRowTooShortForItsCellsIsOneLine() {
        assertThatThrownBy(() -> Worksheet.parse("w.csv", utf8(HEADER + "\r\nParticipant 101,Zoë\r\n")).fill(MARKS))
                .hasMessage("w.csv:2: the row has 2 cells, too few for its Grade and Feedback comments columns");
    }

    /** The cells of a fresh worksheet's rows after the header, read back. */
    private static List<List<String>> freshRows(List<Worksheet.Mark> marks) throws Exception {
        byte[] csv = Worksheet.fresh(marks, 1, ZonedDateTime.of(2026, 1, 2, 3, 4, 5, 0, ZoneId.of("UTC")), null);
        List<List<String>> rows = new ArrayList<>();
        for (CsvRecords.Row row : CsvRecords.read(csv).subList(1, marks.size() + 1)) {
            rows.add(row.cells().stream().map(CsvRecords.Cell::value).toList());
        }
        return rows;
    }

    @Test
    void aCellThatAStudentNamedLikeAFormulaStartsWithAQuoteAsMoodleWritesIt() throws Exception {
        List<String> names = List.of("=SUM(1+1)", "@cmd", "+1", "-2+3", "\tTab", "\rReturn");
        List<Worksheet.Mark> marks = new ArrayList<>();
        for (int i = 0; i < names.size(); i++) {
            marks.add(new Worksheet.Mark(String.valueOf(i), names.get(i), 0, names.get(i)));
        }

        List<List<String>> rows = freshRows(marks);

        for (int i = 0; i < names.size(); i++) {
            assertThat(rows.get(i).get(1)).as("Full name of " + names.get(i)).isEqualTo("'" + names.get(i));
            assertThat(rows.get(i).get(9)).as("Feedback of " + names.get(i)).doesNotStartWith("=")
                    .doesNotStartWith("+").doesNotStartWith("-").doesNotStartWith("@").doesNotStartWith("\t")
                    .doesNotStartWith("\r");
        }
    }

    @Test
    void aFilledFeedbackCellThatStartsLikeAFormulaStartsWithAQuote() throws Exception {
        String input = HEADER + "\r\nParticipant 101,Zoë Ünal,,Submitted for grading,,1.00,Yes,,,,Maths\r\n";

        byte[] output = Worksheet.parse("w.csv", utf8(input)).fill(
                List.of(new Worksheet.Mark("101", "Zoë Ünal", 0, "=HYPERLINK(\"http://x\")"))).bytes();

        assertThat(CsvRecords.read(output).get(1).value(9)).isEqualTo("'=HYPERLINK(\"http://x\")");
    }

    @Test
    void feedbackIsPlainTextSafeToStoreAsHtmlOnOneLine() throws Exception {
        List<List<String>> rows = freshRows(List.of(new Worksheet.Mark("1", "A", 0,
                "src/<img src=x onerror=alert(1)>.zip & more\nsecond line   ( 67.838% of pixels exact)")));

        assertThat(rows.get(0).get(9)).isEqualTo(
                "src/&lt;img src=x onerror=alert(1)&gt;.zip &amp; more second line (67.838% of pixels exact)");
    }

    @Test
    void everyCellIsBoundedWhateverAStudentsArchiveHeld() throws Exception {
        String huge = "x".repeat(5_000_000);

        List<List<String>> rows = freshRows(List.of(new Worksheet.Mark(huge, huge, 0, huge)));

        assertThat(rows.get(0)).allSatisfy(cell -> assertThat(cell.length()).isLessThanOrEqualTo(CellText.MAX_CELL));
    }

    @Test
    void aFreshWorksheetsDateCarriesItsZoneSoMoodleReadsTheRightMoment() {
        ZonedDateTime gradedAt = ZonedDateTime.of(2026, 7, 1, 18, 11, 0, 0, ZoneId.of("Europe/London"));

        String csv = new String(Worksheet.fresh(MARKS, 1, gradedAt, null), StandardCharsets.UTF_8);

        assertThat(csv).contains("\"Wednesday, 1 July 2026, 6:11 PM +01:00\"");
    }

    @Test
    void aMarkWithoutAGradeLeavesTheGradeCellBlank() throws Exception {
        List<List<String>> rows = freshRows(List.of(new Worksheet.Mark("1", "A", null, "no Renderer.java")));

        assertThat(rows.get(0).get(4)).isEmpty();
        assertThat(rows.get(0).get(5)).isEqualTo("1.00");
    }

    @Test
    void theWorksheetsMaximumGradeIsTheOneItsRowsShare() throws Exception {
        String input = HEADER + "\r\nParticipant 1,A,,,,10.00,Yes,,,,x\r\nParticipant 2,B,,,,10.00,Yes,,,,x\r\n";

        assertThat(Worksheet.parse("w.csv", utf8(input)).maximumGrade()).isEqualTo(10.0);
        assertThat(Worksheet.parse("w.csv", utf8(HEADER + "\r\n")).maximumGrade()).isNull();
    }

    @Test
    void rowsWithDifferentMaximumGradesAreOneLine() {
        String input = HEADER + "\r\nParticipant 1,A,,,,10.00,Yes,,,,x\r\nParticipant 2,B,,,,5.00,Yes,,,,x\r\n";

        assertThatThrownBy(() -> Worksheet.parse("w.csv", utf8(input)).maximumGrade())
                .hasMessage("w.csv:3: the row's Maximum Grade 5.00 differs from the rows above (10.00)");
    }

    @Test
    void aZipGivenAsTheWorksheetSaysWhatItIsAndWhatWasExpected() {
        byte[] zip = {'P', 'K', 3, 4, 20, 0, 0, 0, (byte) 0x81, 1, 2};

        assertThatThrownBy(() -> Worksheet.parse("download.zip", zip)).isInstanceOf(CohortInputException.class)
                .hasMessageStartingWith("download.zip: a zip archive, not a worksheet: --worksheet wants the grading "
                        + "worksheet downloaded from the assignment, as CSV")
                .hasMessageNotContaining("\n");
    }
}
