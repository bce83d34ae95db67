package gfx.tick1.command.shared.grader.lookalike;

import gfx.tick1.command.shared.javacode.JavaMembers;
import gfx.tick1.command.shared.javacode.ReferenceMembers;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;

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
    /** Changes when what a parse keeps changes, so that code kept by an older reader is parsed again. */
    private static final String FORMAT = "tick1 parsed code 2";

    private final int minimum;
    private final ParsedCodes parsed;
    /** Each token's text (a local's as {@link #LOCAL}) to its number, shared by every code this reader reads. */
    private final Map<String, Integer> vocabulary = new ConcurrentHashMap<>();
    private final AtomicInteger words = new AtomicInteger();
    /** tick1's and the starter's files parsed, when a file must be parsed: JavaParser is not loaded before. */
    private Tick1Code tick1;
    private final ComparedCode starter;
    private final ComparedCode referenceCode;

    /** tick1's own Sphere and Renderer parsed, and the members of the starter's, which a student's read sets aside. */
    private record Tick1Code(Map<String, JavaMembers> reference, JavaMembers sphere, JavaMembers renderer,
            Map<String, Set<String>> starterMembers) {

        static Tick1Code parse() {
            Map<String, JavaMembers> reference = Map.of("Sphere", ReferenceMembers.ours("Sphere"),
                    "Renderer", ReferenceMembers.ours("Renderer"));
            JavaMembers sphere = ReferenceMembers.starter("Sphere", reference.get("Sphere"));
            JavaMembers renderer = ReferenceMembers.starter("Renderer", reference.get("Renderer"));
            return new Tick1Code(reference, sphere, renderer, Map.of("Sphere", sphere.members().keySet(),
                    "Renderer", renderer.members().keySet()));
        }
    }

    /** A reader whose codes are prepared for tiles of at least {@code minimum} tokens, parsing every file. */
    CodeReader(int minimum) {
        this(minimum, ParsedCodes.NONE);
    }

    /**
     * A reader whose codes are prepared for tiles of at least {@code minimum} tokens, which takes code parsed
     * before from {@code parsed}, and keeps there what it parses.
     */
    CodeReader(int minimum, ParsedCodes parsed) {
        this.minimum = minimum;
        this.parsed = parsed;
        starter = tokens(kept(digest("starter", null, null), () -> {
            Tick1Code code = tick1();
            return select(List.of(code.sphere(), code.renderer()), List.of());
        }), null);
        referenceCode = tokens(kept(digest("reference", null, null), () -> {
            Tick1Code code = tick1();
            return select(List.of(code.reference().get("Sphere"), code.reference().get("Renderer")), List.of());
        }), starter);
    }

    private synchronized Tick1Code tick1() {
        if (tick1 == null) {
            tick1 = Tick1Code.parse();
        }
        return tick1;
    }

    /** The code kept under {@code digest}, else {@code parse}'s, then kept. */
    private ParsedCode kept(String digest, Supplier<ParsedCode> parse) {
        ParsedCode code = parsed.get(digest);
        if (code == null) {
            code = parse.get();
            parsed.put(digest, code);
        }
        return code;
    }

    /**
     * The digest of what is parsed: SHA-256 of this reader's format, the {@code kind} of code ("student", or tick1's
     * own "starter" and "reference", whose files are part of tick1) and the two files' text (null: not submitted),
     * each preceded by its length, so that no two different inputs make the same bytes. It does not cover tick1's
     * own code: a {@link ParsedCodes} that outlives a build of tick1 keeps each build's apart.
     */
    static String digest(String kind, String sphere, String renderer) {
        MessageDigest sha;
        try {
            sha = MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
        for (String part : new String[] {FORMAT, kind, sphere == null ? "-" : "+" + sphere,
                renderer == null ? "-" : "+" + renderer}) {
            byte[] bytes = part.getBytes(StandardCharsets.UTF_8);
            sha.update(ByteBuffer.allocate(Long.BYTES).putLong(bytes.length).array());
            sha.update(bytes);
        }
        return HexFormat.of().formatHex(sha.digest());
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
        return tokens(kept(digest("student", sphere, renderer), () -> {
            List<JavaMembers> files = new ArrayList<>();
            List<String> notes = new ArrayList<>();
            parse("Sphere", sphere, files, notes);
            parse("Renderer", renderer, files, notes);
            return select(files, notes);
        }), starter);
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
                Set<String> given = tick1().starterMembers().get(className);
                JavaMembers members = JavaMembers.parse(file, source, tick1().reference().get(className),
                        signature -> signature.equals(own) || !given.contains(signature));
                parsed.add(new JavaMembers(className, members.members()));
                members.tooDeep().forEach(member -> notes.add(member.signature() + " in " + file
                        + " is not compared: " + member.why()));
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

    /** The members compared of each file: the tick's own method, and those the starter does not have. */
    private ParsedCode select(List<JavaMembers> files, List<String> notes) {
        Map<String, Set<String>> starterMembers = tick1().starterMembers();
        List<ComparedCode.Member> members = new ArrayList<>();
        for (JavaMembers file : files) {
            String own = file.className().equals("Sphere") ? INTERSECTION : ILLUMINATE;
            for (Map.Entry<String, JavaMembers.Member> entry : file.members().entrySet()) {
                String signature = entry.getKey();
                if (signature.equals(own) || !starterMembers.get(file.className()).contains(signature)) {
                    members.add(new ComparedCode.Member(file.className() + ".java", signature,
                            entry.getValue().key()));
                }
            }
        }
        return new ParsedCode(members, notes);
    }

    /** The code's members tokenised, at most {@link #MOST_TOKENS}, the base's set aside ({@code base} null: none). */
    private ComparedCode tokens(ParsedCode code, ComparedCode base) {
        List<ComparedCode.Member> members = new ArrayList<>();
        List<String> allNotes = new ArrayList<>(code.notes());
        int[] tokens = new int[64];
        int[] memberOf = new int[64];
        int[] starts = new int[64];
        int[] ends = new int[64];
        int count = 0;
        boolean full = false;
        for (ComparedCode.Member member : code.members()) {
            if (full) {
                break;
            }
            String text = member.text();
            int[] spans = JavaTokens.spans(text);
            members.add(member);
            for (int s = 0; s < spans.length; s += 2) {
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
