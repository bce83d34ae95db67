package gfx.tick1.command.shared.grader.lookalike;

import gfx.tick1.command.shared.javacode.JavaMembers;
import gfx.tick1.command.shared.javacode.ReferenceMembers;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Reads students' Sphere.java and Renderer.java into {@link ComparedCode}: each file parsed as
 * {@code tick1 diff} parses it ({@link JavaMembers}: comments, layout and parentheses that change
 * nothing set aside, independent declarations in the reference's order), the members compared
 * taken, and their canonical text cut into tokens. Every local and parameter is one token kind
 * ("a local"), whatever its name and number: a declaration added or dropped renumbers every local
 * after it, and must not hide the runs that follow. The starter code's tokens found by tiling
 * against the starter (the base) are set aside.
 */
final class CodeReader {

    /** The methods the tick asks for, one in each file. */
    static final String INTERSECTION = "intersectionWith(Ray)";
    static final String ILLUMINATE = "illuminate(Scene, Sphere, Vector3, Vector3)";
    /** The most tokens of a submission compared: ten times a full solution's; the rest is left out, and said so. */
    static final int MOST_TOKENS = 4_000;
    /** The largest file parsed for comparing, in characters: a real one is a few thousand. */
    static final int MOST_CHARACTERS = 200_000;

    private static final String LOCAL = "#";

    private final int minimum;
    /** Each token's text (a local's as {@link #LOCAL}) to its number, shared by every code this reader reads. */
    private final Map<String, Integer> vocabulary = new ConcurrentHashMap<>();
    private final AtomicInteger words = new AtomicInteger();
    private final Map<String, JavaMembers> reference = Map.of("Sphere", ReferenceMembers.ours("Sphere"),
            "Renderer", ReferenceMembers.ours("Renderer"));
    private final Map<String, Set<String>> starterMembers;
    private final ComparedCode starter;
    private final ComparedCode referenceCode;

    /** A reader whose codes are prepared for tiles of at least {@code minimum} tokens. */
    CodeReader(int minimum) {
        this.minimum = minimum;
        JavaMembers sphere = ReferenceMembers.starter("Sphere", reference.get("Sphere"));
        JavaMembers renderer = ReferenceMembers.starter("Renderer", reference.get("Renderer"));
        starterMembers = Map.of("Sphere", sphere.members().keySet(), "Renderer", renderer.members().keySet());
        starter = read(List.of(sphere, renderer), List.of(), null);
        referenceCode = read(List.of(reference.get("Sphere"), reference.get("Renderer")), List.of(), starter);
    }

    /** tick1's own Sphere and Renderer, read as a student's are. */
    ComparedCode reference() {
        return referenceCode;
    }

    /** The starter's two methods, the base. */
    ComparedCode starter() {
        return starter;
    }

    /** A student's two files (either may be null: not submitted), read for comparing. */
    ComparedCode read(String sphere, String renderer) {
        List<JavaMembers> parsed = new ArrayList<>();
        List<String> notes = new ArrayList<>();
        parse("Sphere", sphere, parsed, notes);
        parse("Renderer", renderer, parsed, notes);
        return read(parsed, notes, starter);
    }

    private void parse(String className, String source, List<JavaMembers> parsed, List<String> notes) {
        String file = className + ".java";
        if (source == null) {
            notes.add(file + " is missing");
        } else if (source.length() > MOST_CHARACTERS) {
            notes.add(file + " is longer than " + MOST_CHARACTERS + " characters");
        } else {
            try {
                String own = className.equals("Sphere") ? INTERSECTION : ILLUMINATE;
                Set<String> given = starterMembers.get(className);
                JavaMembers members = JavaMembers.parse(file, source, reference.get(className),
                        signature -> signature.equals(own) || !given.contains(signature));
                parsed.add(new JavaMembers(className, members.members()));
            } catch (JavaMembers.ParseException e) {
                notes.add(file + " does not parse");
            } catch (StackOverflowError e) {
                notes.add(file + " is nested too deeply to parse");
            } catch (RuntimeException e) {
                // A hostile file must cost its own comparison, never the cohort's report.
                notes.add(file + " could not be read for comparing");
            }
        }
    }

    /** The members compared of each file, tokenised, with the base's tokens set aside ({@code base} null: none). */
    private ComparedCode read(List<JavaMembers> files, List<String> notes, ComparedCode base) {
        List<ComparedCode.Member> members = new ArrayList<>();
        List<String> allNotes = new ArrayList<>(notes);
        int[] tokens = new int[64];
        int[] memberOf = new int[64];
        int[] starts = new int[64];
        int[] ends = new int[64];
        int count = 0;
        boolean full = false;
        for (JavaMembers file : files) {
            String own = file.className().equals("Sphere") ? INTERSECTION : ILLUMINATE;
            for (Map.Entry<String, JavaMembers.Member> entry : file.members().entrySet()) {
                String signature = entry.getKey();
                if (full || !signature.equals(own) && starterMembers.get(file.className()).contains(signature)) {
                    continue;
                }
                String text = entry.getValue().key();
                int[] spans = JavaTokens.spans(text);
                members.add(new ComparedCode.Member(file.className() + ".java", signature, text));
                for (int s = 0; s < spans.length && !full; s += 2) {
                    if (count == MOST_TOKENS) {
                        full = true;
                        allNotes.add("only the first " + MOST_TOKENS + " tokens are compared");
                        break;
                    }
                    if (count == tokens.length) {
                        tokens = Arrays.copyOf(tokens, count * 2);
                        memberOf = Arrays.copyOf(memberOf, count * 2);
                        starts = Arrays.copyOf(starts, count * 2);
                        ends = Arrays.copyOf(ends, count * 2);
                    }
                    String token = text.substring(spans[s], spans[s + 1]);
                    tokens[count] = vocabulary.computeIfAbsent(token.startsWith(LOCAL) ? LOCAL : token,
                            key -> words.getAndIncrement());
                    memberOf[count] = members.size() - 1;
                    starts[count] = spans[s];
                    ends[count] = spans[s + 1];
                    count++;
                }
            }
        }
        ComparedCode.Tokens read = new ComparedCode.Tokens(Arrays.copyOf(tokens, count),
                Arrays.copyOf(memberOf, count), Arrays.copyOf(starts, count), Arrays.copyOf(ends, count));
        boolean[] setAside = new boolean[count];
        if (base != null) {
            ComparedCode unmarked = new ComparedCode(members, allNotes, read, setAside, minimum);
            for (GreedyStringTiling.Tile tile : GreedyStringTiling.tiles(unmarked.sequence, base.sequence)) {
                Arrays.fill(setAside, tile.a(), tile.a() + tile.length(), true);
            }
        }
        return new ComparedCode(members, allNotes, read, setAside, minimum);
    }
}
