package gfx.tick1.command.shared.javacode;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/**
 * Code nested more deeply than any solution ({@link Nesting}) is not compared, as its text would grow as the square
 * of its depth: a member too deep, or past the file's bound on nesting in all, is left out of the members, with
 * where, and the rest of the file is compared as usual.
 */
class JavaMembersNestingTest {

    /** A class with a field, a method, and {@code deep()}: blocks nested {@code depth} deep. */
    private static JavaMembers parseWithBlocks(int depth) throws JavaMembers.ParseException {
        return JavaMembers.parse("T.java", "class T {\n    double f;\n    double next() { return f + 1; }\n"
                + "    void deep() " + "{".repeat(depth) + "}".repeat(depth) + "\n}\n");
    }

    @Test
    void aMemberNestedBeyondTheBoundIsLeftOutAndTheRestIsCompared() throws Exception {
        JavaMembers parsed = parseWithBlocks(Nesting.MOST_DEPTH + 1);

        assertThat(parsed.members()).as("the members compared").containsOnlyKeys("field f", "next()");
    }

    /** Members each within the bound on depth, whose nesting adds up past the file's: each one from there on. */
    @Test
    void membersWhoseNestingAddsUpPastTheFilesBoundAreLeftOutFromWhereItIsPassed() throws Exception {
        int depth = Nesting.MOST_DEPTH;
        long eachOne = (long) depth * (depth + 1) / 2;
        int within = (int) (Nesting.MOST_TOTAL / eachOne);
        StringBuilder source = new StringBuilder("class T {\n");
        for (int i = 0; i <= within; i++) {
            source.append("    void m").append(i).append("() ").append("{".repeat(depth)).append("}".repeat(depth))
                    .append("\n");
        }
        JavaMembers parsed = JavaMembers.parse("T.java", source.append("}\n").toString());

        assertThat(parsed.members()).as("the members compared").hasSize(within);
        assertThat(parsed.tooDeep()).as("the member left out").singleElement().satisfies(member -> assertThat(
                member.message()).isEqualTo("T.java:" + (within + 2) + ":5: m" + within + "(): the depths of the "
                + "file's blocks, statements and expressions, added up, pass " + Nesting.MOST_TOTAL
                + ": too deeply nested to compare"));
    }

    @Test
    void aMemberNestedToTheBoundIsCompared() throws Exception {
        JavaMembers parsed = parseWithBlocks(Nesting.MOST_DEPTH);

        assertThat(parsed.members()).as("the members compared").containsOnlyKeys("field f", "next()", "deep()");
    }
}
