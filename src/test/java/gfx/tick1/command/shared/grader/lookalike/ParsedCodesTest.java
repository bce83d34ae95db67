package gfx.tick1.command.shared.grader.lookalike;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.grader.lookalike.Handwritten.Solution;
import gfx.tick1.command.shared.grader.model.StudentResult;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.junit.jupiter.api.Test;

/** The look-alike check keeps the code it parses, and a later check takes it from there instead of parsing. */
class ParsedCodesTest {

    private static final List<Solution> HONEST = Handwritten.cohort();

    /** Keeps parsed code in a map, as a report folder keeps it in files. */
    private static final class Kept implements ParsedCodes {
        final Map<String, ParsedCode> codes = new ConcurrentHashMap<>();

        @Override
        public ParsedCode get(String digest) {
            return codes.get(digest);
        }

        @Override
        public void put(String digest, ParsedCode code) {
            codes.put(digest, code);
        }
    }

    @Test
    void aStudentsFilesParsedBeforeAreTakenFromWhereTheyAreKeptNotParsedAgain() {
        Kept kept = new Kept();
        Solution first = HONEST.get(0);
        Solution second = HONEST.get(1);
        new CodeReader(Lookalikes.MINIMUM_MATCH, kept).read(second.sphere(), second.renderer());
        ParsedCode ofSecond = kept.codes.get(CodeReader.digest("student", second.sphere(), second.renderer()));
        // The first's digest now names the second's code: a reader that parsed the first's files would not see it.
        kept.codes.put(CodeReader.digest("student", first.sphere(), first.renderer()), ofSecond);

        ComparedCode read = new CodeReader(Lookalikes.MINIMUM_MATCH, kept).read(first.sphere(), first.renderer());

        assertThat(read.members()).as("the members read for the first student's files").isEqualTo(
                ofSecond.members());
    }

    @Test
    void tick1sOwnCodeIsTakenFromWhereItIsKeptToo() {
        Kept kept = new Kept();
        new CodeReader(Lookalikes.MINIMUM_MATCH, kept);
        ParsedCode planted = new ParsedCode(List.of(new ComparedCode.Member("Sphere.java", "intersectionWith(Ray)",
                "return null;")), List.of());
        kept.codes.put(CodeReader.digest("reference", null, null), planted);

        CodeReader reader = new CodeReader(Lookalikes.MINIMUM_MATCH, kept);

        assertThat(reader.reference().members()).as("the reference's members").isEqualTo(planted.members());
    }

    @Test
    void theLookalikesFoundWithKeptCodeAreThoseFoundByParsing() throws InterruptedException {
        List<Solution> cohort = new ArrayList<>(HONEST);
        cohort.addAll(List.of(LookalikesTest.RENAMED_AND_REORDERED, LookalikesTest.COMMENTS_AND_LAYOUT,
                LookalikesTest.WRONG, LookalikesTest.SAME_WRONG, LookalikesTest.REFERENCE_COPY));
        List<StudentResult> results = new ArrayList<>();
        for (int i = 0; i < cohort.size(); i++) {
            results.add(LookalikesTest.result(i + 1, cohort.get(i), List.of()));
        }
        Kept kept = new Kept();
        Lookalikes.find(results, kept);

        List<String> parsed = described(Lookalikes.find(results));
        List<String> fromKept = described(Lookalikes.find(results, kept));

        assertThat(fromKept).as("the look-alikes found with the code kept").isNotEmpty().isEqualTo(parsed);
    }

    /** Each look-alike as its pair, why, similarity and the marked spans of both sides' members. */
    private static List<String> described(List<Lookalike> found) {
        return found.stream().map(pair -> pair.a().fullName() + " / " + (pair.b() == null ? "reference"
                : pair.b().fullName()) + " " + pair.why() + " " + pair.similarity() + " " + pair.compared().codeA()
                .members() + pair.compared().codeA().spans(pair.compared().sharedOfA()) + " " + pair.compared()
                .codeB().members() + pair.compared().codeB().spans(pair.compared().sharedOfB())).toList();
    }
}
