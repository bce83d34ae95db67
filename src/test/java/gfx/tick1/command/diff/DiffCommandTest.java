package gfx.tick1.command.diff;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.CliRun;
import gfx.tick1.command.shared.behaviour.Variant;
import gfx.tick1.command.shared.behaviour.WrittenStyles;
import gfx.tick1.command.shared.grader.sandbox.RefusedNamespaces;
import gfx.tick1.command.shared.javacode.JavaMembers;
import gfx.tick1.command.shared.javacode.ReferenceMembers;
import gfx.tick1.command.shared.kit.StarterKit;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.MethodSource;

/** {@code tick1 diff} through the real entry point. */
@org.junit.jupiter.api.Order(2)   // one of the longest classes: it starts early (junit-platform.properties)
class DiffCommandTest {

    private static final String ILLUMINATE = "illuminate(Scene, Sphere, Vector3, Vector3)";
    private static final String INTERSECTION = "intersectionWith(Ray)";
    private static final String RENDER = "render(Scene)";
    private static final String TRACE = "trace(Scene, Ray)";
    private static final String RGB = "image.setRGB(x, y, linearRGB.toRGB());";

    @TempDir
    Path dir;

    /** Where the styles' files are written for {@link #diffOf}: one folder per style. */
    @TempDir
    static Path styles;
    private static final java.util.Map<CorrectStyles.Style, CliRun> STYLE_RUNS = new java.util.HashMap<>();

    private Path write(String name, String source) throws IOException {
        Path file = dir.resolve(name);
        Files.writeString(file, source);
        return file;
    }

    private static String ours(String name) throws IOException {
        return Files.readString(Path.of(name.equals("Sphere") ? "src/main/java/gfx/tick1/engine/scene/Sphere.java"
                : "src/main/java/gfx/tick1/engine/render/Renderer.java"));
    }

    /** Our file with its comments removed, every line re-indented, its members in reverse order. */
    private static String reformatted(String source) {
        String noComments = source.replaceAll("(?s)/\\*.*?\\*/", "").replaceAll("//[^\n]*", "");
        String body = noComments.substring(noComments.indexOf('{', noComments.indexOf("class ")) + 1,
                noComments.lastIndexOf('}'));
        // Split the body into members at the lines that start one (four spaces of indent, then a word).
        java.util.List<String> members = new java.util.ArrayList<>();
        StringBuilder member = new StringBuilder();
        int depth = 0;
        for (String line : body.split("\n")) {
            member.append("  ").append(line.strip()).append("\n");
            depth += line.chars().filter(c -> c == '{').count() - line.chars().filter(c -> c == '}').count();
            if (depth == 0 && (line.strip().endsWith(";") || line.strip().endsWith("}"))) {
                members.add(member.toString());
                member.setLength(0);
            }
        }
        java.util.Collections.reverse(members);
        String header = noComments.substring(0, noComments.indexOf('{', noComments.indexOf("class ")) + 1);
        return header.replace("package ", "\n\npackage  ") + "\n" + String.join("\n\n", members) + "}\n";
    }

    @Test
    void ourOwnFilesReformattedWithoutCommentsAndReorderedGiveExitZeroAndNoOutput() throws IOException {
        Path sphere = write("Sphere.java", reformatted(ours("Sphere")));
        Path renderer = write("Renderer.java", reformatted(ours("Renderer")));
        assertThat(Files.readString(sphere)).isNotEqualTo(ours("Sphere")).doesNotContain("//");
        CliRun run = CliRun.of("diff", sphere.toString(), renderer.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_SAME);
        assertThat(run.out()).as(run.transcript()).isEmpty();
        assertThat(run.err()).isEmpty();
    }

    @Test
    void theStudentsCorrectSolutionDiffersInNothing() throws IOException {
        CliRun run = CliRun.of("diff", "src/test/resources/students/correct/Renderer.java",
                "src/test/resources/students/correct/Sphere.java");
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_SAME);
        assertThat(run.out()).isEmpty();
    }

    /** The mistake edits the grade tests make, on our own files. */
    static Stream<Arguments> mistakes() {
        return Stream.of(
                Arguments.of(Variant.FAR_ROOT, "Sphere", INTERSECTION, "double s = s1 > 0 ? s1 : s2;",
                        "double s = s2;"),
                Arguments.of(Variant.HIT_REJECTED_ON_A_NEGATIVE_ROOT, "Sphere", INTERSECTION,
                        "double s = s1 > 0 ? s1 : s2;",
                        "if (s1 < 0 || s2 < 0) { return new RaycastHit(); } double s = s1 > 0 ? s1 : s2;"),
                Arguments.of(Variant.AMBIENT_ONLY, "Renderer", ILLUMINATE,
                        "return ambient.add(diffuse).add(specular);", "return ambient;"),
                Arguments.of(Variant.AMBIENT_DIFFUSE, "Renderer", ILLUMINATE,
                        "return ambient.add(diffuse).add(specular);", "return ambient.add(diffuse);"),
                Arguments.of(Variant.AMBIENT_WITHOUT_C_DIFF, "Renderer", ILLUMINATE,
                        "Vector3 ambient = C_diff.scale(I_a);", "Vector3 ambient = I_a;"),
                Arguments.of(Variant.SPECULAR_WITHOUT_I, "Renderer", ILLUMINATE,
                        "C_spec.scale(I).scale(k_s", "C_spec.scale(k_s"),
                // V alone not normalised: no entry's model gives its answers (the catalogue's leaves L so too).
                Arguments.of(null, "Renderer", ILLUMINATE,
                        "Vector3 V = P.scale(-1).normalised();", "Vector3 V = P.scale(-1);"),
                Arguments.of(Variant.UNCLAMPED_N_DOT_L, "Renderer", ILLUMINATE,
                        "k_d * Math.max(0, NdotL)", "k_d * NdotL"),
                Arguments.of(Variant.UNCLAMPED_R_DOT_V, "Renderer", ILLUMINATE,
                        "Math.pow(Math.max(0, RdotV), n)", "Math.pow(RdotV, n)"),
                Arguments.of(Variant.NO_FALL_OFF, "Renderer", ILLUMINATE, "light.getIlluminationAt(distanceToLight)",
                        "light.getColour().scale(light.getIntensity() / (Math.PI * 4))"),
                Arguments.of(Variant.FALL_OFF_WITHOUT_4PI, "Renderer", ILLUMINATE,
                        "light.getIlluminationAt(distanceToLight)",
                        "light.getColour().scale(light.getIntensity() / Math.pow(distanceToLight, 2))"),
                Arguments.of(Variant.V_AWAY_FROM_CAMERA, "Renderer", ILLUMINATE,
                        "Vector3 V = P.scale(-1).normalised();", "Vector3 V = P.normalised();"),
                Arguments.of(Variant.R_WRONG_WAY, "Renderer", ILLUMINATE, "L.reflectIn(N)", "N.reflectIn(L)"),
                Arguments.of(Variant.ROUNDED_BYTES, "Renderer", RENDER, RGB, "image.setRGB(x, y, "
                        + "(int) Math.round(255 * Math.max(0, Math.min(1, linearRGB.x))) << 16 "
                        + "| (int) Math.round(255 * Math.max(0, Math.min(1, linearRGB.y))) << 8 "
                        + "| (int) Math.round(255 * Math.max(0, Math.min(1, linearRGB.z))));"),
                Arguments.of(Variant.UPSIDE_DOWN, "Renderer", RENDER, RGB,
                        "image.setRGB(x, height - 1 - y, linearRGB.toRGB());"),
                Arguments.of(Variant.RED_BLUE_SWAPPED, "Renderer", RENDER, RGB,
                        "image.setRGB(x, y, new Vector3(linearRGB.z, linearRGB.y, linearRGB.x).toRGB());"),
                Arguments.of(Variant.UNCHECKED_NEGATIVE_SQUARE_ROOT, "Sphere", INTERSECTION,
                        "if (discriminant < 0) {\n            return new RaycastHit();\n        }\n", ""));
    }

    static Stream<CorrectStyles.Style> layoutOnly() {
        return CorrectStyles.layoutOnly().stream();
    }

    static Stream<CorrectStyles.Style> otherCode() {
        return CorrectStyles.otherCode().stream();
    }

    private static java.util.Set<String> membersShown(CliRun run) {
        return run.out().lines().filter(line -> line.startsWith("@@ "))
                .map(line -> line.substring(3, line.length() - 3)
                        .replaceFirst(" \\((only in|missing from) yours\\)$", ""))
                .collect(java.util.stream.Collectors.toSet());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("layoutOnly")
    void aCorrectSolutionThatDiffersOnlyInLayoutExitsZeroAndPrintsNothing(CorrectStyles.Style style)
            throws IOException {
        Path[] files = style.writeTo(dir.resolve("style"));
        CliRun run = CliRun.of("diff", files[0].toString(), files[1].toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_SAME);
        assertThat(run.out()).as(run.transcript()).isEmpty();
        assertThat(run.err()).isEmpty();
    }

    /** {@link #diffOf}, where the sandbox can be made (else the test is skipped): the methods' behaviour is said. */
    private static CliRun sandboxedDiffOf(CorrectStyles.Style style) throws IOException, InterruptedException {
        org.junit.jupiter.api.Assumptions.assumeTrue(sandboxHere(), "the sandbox can be made here");
        return diffOf(style);
    }

    /**
     * {@code tick1 diff} of a style's two files, run once per style, on first use, for the tests that
     * read its differences and its hints: each run compiles and probes the files in the sandbox.
     */
    private static synchronized CliRun diffOf(CorrectStyles.Style style) throws IOException {
        CliRun run = STYLE_RUNS.get(style);
        if (run == null) {
            Path[] files = style.writeTo(styles.resolve("style-" + STYLE_RUNS.size()));
            run = CliRun.of("diff", files[0].toString(), files[1].toString());
            STYLE_RUNS.put(style, run);
        }
        return run;
    }

    /** A run that more than one test reads, made in a folder of its own. */
    private interface SharedRun {
        CliRun in(Path folder) throws IOException, InterruptedException;
    }

    private static final java.util.Map<String, CliRun> SHARED_RUNS = new java.util.HashMap<>();

    /** The run named {@code name}, made once, on first use, in the folder of that name: each diff costs seconds. */
    private static synchronized CliRun shared(String name, SharedRun run) throws IOException, InterruptedException {
        CliRun made = SHARED_RUNS.get(name);
        if (made == null) {
            made = run.in(Files.createDirectories(styles.resolve(name)));
            SHARED_RUNS.put(name, made);
        }
        return made;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("otherCode")
    void aCorrectSolutionWrittenAnotherWayShowsTheMembersItChangesAndNoOthers(CorrectStyles.Style style)
            throws IOException {
        CliRun run = diffOf(style);
        assertThat(membersShown(run)).as(run.transcript()).isEqualTo(style.changedMembers());
    }

    /** The form part of diff of one of a style's files, as {@link DiffCommand#compare} gives it, uncoloured. */
    private record FormDiff(JavaMembers ours, JavaMembers theirs, java.util.List<String> report) {

        static FormDiff of(String className, String source) throws JavaMembers.ParseException {
            JavaMembers ours = ReferenceMembers.ours(className);
            JavaMembers theirs = JavaMembers.parse(className + ".java", source, ours);
            JavaMembers starter = ReferenceMembers.starter(className, ours);
            return new FormDiff(ours, theirs, DiffCommand.compare(ours, starter, theirs,
                    Path.of(className + ".java"), new DiffCommand.Colours(false)));
        }

        /** Each hunk's lines (kind and text), under the signature of the member it belongs to. */
        java.util.List<java.util.Map.Entry<String, java.util.List<String>>> hunks() {
            java.util.List<java.util.Map.Entry<String, java.util.List<String>>> hunks = new java.util.ArrayList<>();
            for (String line : report) {
                if (line.startsWith("@@ ")) {
                    String signature = line.substring(3, line.length() - 3).replaceFirst(" \\(.*\\)$", "");
                    hunks.add(java.util.Map.entry(signature, new java.util.ArrayList<>()));
                } else if (!hunks.isEmpty()) {
                    hunks.get(hunks.size() - 1).getValue().add(line);
                }
            }
            return hunks;
        }

        /** The texts of a hunk's lines of one kind ('-', '+' or ' '). */
        static java.util.List<String> texts(java.util.List<String> hunk, char kind) {
            return hunk.stream().filter(line -> line.charAt(0) == kind).map(line -> line.substring(1)).toList();
        }

        static java.util.List<String> lines(JavaMembers members, String signature) {
            JavaMembers.Member member = members.members().get(signature);
            return member == null ? java.util.List.of() : member.lines();
        }
    }

    private static Stream<Arguments> styleFiles() {
        return Stream.concat(CorrectStyles.layoutOnly().stream(), CorrectStyles.otherCode().stream())
                .flatMap(style -> Stream.of(Arguments.of(style, "Sphere", style.sphere()),
                        Arguments.of(style, "Renderer", style.renderer())));
    }

    @ParameterizedTest(name = "{0}: {1}")
    @MethodSource("styleFiles")
    void noLineOfACorrectStyleIsShownAsRemovedAndAddedAgain(CorrectStyles.Style style, String className,
            String source) throws Exception {
        FormDiff diff = FormDiff.of(className, source);
        diff.hunks().forEach(hunk -> assertThat(FormDiff.texts(hunk.getValue(), '+'))
                .as("a line of %s shown as removed and added again:%n%s", hunk.getKey(),
                        String.join("\n", diff.report()))
                .noneMatch(FormDiff.texts(hunk.getValue(), '-')::contains));
    }

    @ParameterizedTest(name = "{0}: {1}")
    @MethodSource("styleFiles")
    void contextAndAddedLinesAreTheStudentsOwnAndRemovedLinesOurs(CorrectStyles.Style style, String className,
            String source) throws Exception {
        FormDiff diff = FormDiff.of(className, source);
        for (java.util.Map.Entry<String, java.util.List<String>> hunk : diff.hunks()) {
            java.util.List<String> theirs = FormDiff.lines(diff.theirs(), hunk.getKey());
            java.util.List<String> ours = FormDiff.lines(diff.ours(), hunk.getKey());
            for (String line : hunk.getValue()) {
                assertThat(line.charAt(0) == '-' ? ours : theirs)
                        .as("the line \"%s\" of %s in %s's words:%n%s", line, hunk.getKey(),
                                line.charAt(0) == '-' ? "our" : "the student", String.join("\n", diff.report()))
                        .contains(line.substring(1));
            }
        }
    }

    /** The members whose meaning the behaviour comparison checks by running them. */
    private static final Set<String> RUN = Set.of(INTERSECTION, ILLUMINATE, "getNormalAt(Vector3)");

    /**
     * A correct solution whose only differences are in the methods the comparison runs (and in helpers
     * of its own that only they call) behaves as ours, whatever its form: exit 0; one that also changes
     * another member of ours (render, a constructor) exits 1.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("otherCode")
    void aCorrectSolutionExitsZeroWhenOnlyTheMethodsThatBehaveAsOursDiffer(CorrectStyles.Style style)
            throws IOException, InterruptedException {
        CliRun run = sandboxedDiffOf(style);
        boolean onlyRunMembersOfOursChanged = style.changedMembers().stream()
                .filter(signature -> ReferenceMembers.ours("Sphere").members().containsKey(signature)
                        || ReferenceMembers.ours("Renderer").members().containsKey(signature))
                .allMatch(RUN::contains);
        assertThat(run.status()).as(run.transcript())
                .isEqualTo(onlyRunMembersOfOursChanged ? DiffCommand.EXIT_SAME : DiffCommand.EXIT_DIFFERENT);
        assertThat(run.out().lines().filter(line -> line.contains(" behaves as ours on "))).as(run.transcript())
                .hasSize(2);
    }

    /**
     * Code whose methods behave as ours, and that changes nothing else of ours in meaning, is told
     * first that there is nothing to fix, and its hunks come under a heading that says they are of
     * form; code that changes something else (render, a constructor) is never told so.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("otherCode")
    void theFirstLineSaysThereIsNothingToFixExactlyWhenTheCodeDoesWhatOursDoes(CorrectStyles.Style style)
            throws IOException, InterruptedException {
        CliRun run = sandboxedDiffOf(style);
        java.util.List<String> lines = run.out().lines().toList();

        if (run.status() == DiffCommand.EXIT_SAME) {
            assertThat(lines.get(0)).as(run.transcript()).isEqualTo(DiffCommand.NOTHING_TO_FIX);
            assertThat(lines.indexOf(DiffCommand.FORM_ONLY)).as(run.transcript()).isPositive()
                    .isLessThan(lines.indexOf(lines.stream().filter(line -> line.startsWith("--- ours: "))
                            .findFirst().orElseThrow()));
        } else {
            assertThat(lines).as(run.transcript()).doesNotContain(DiffCommand.NOTHING_TO_FIX, DiffCommand.FORM_ONLY);
        }
    }

    /**
     * The kit as handed out, in our layout and in the course's own (which writes
     * {@code this.phong_kD = SPHERE_KD} and calls the traced colour {@code pixel}): only the two
     * methods the student writes differ.
     */
    @ParameterizedTest(name = "the course''s layout: {0}")
    @org.junit.jupiter.params.provider.ValueSource(booleans = {false, true})
    void theUntouchedStarterCodeShowsOnlyIntersectionWithAndIlluminate(boolean coursesLayout) throws IOException {
        String sphere = StarterKit.source("Sphere"), renderer = StarterKit.source("Renderer");
        if (coursesLayout) {
            sphere = sphere.replace("        phong_", "        this.phong_");
            renderer = renderer.replace("linearRGB", "pixel");
            assertThat(sphere).contains("this.phong_kD = SPHERE_KD;");
            assertThat(renderer).contains("pixel.toRGB()");
        }
        CliRun run = CliRun.of("diff", write("Sphere.java", sphere).toString(),
                write("Renderer.java", renderer).toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_DIFFERENT);
        assertThat(membersShown(run)).as(run.transcript()).containsExactlyInAnyOrder(INTERSECTION, ILLUMINATE);
    }

    /** Edits that change what the code computes, each as small as an edit can be. */
    @ParameterizedTest(name = "{1} -> {2}")
    @CsvSource(delimiter = '|', value = {
        "Sphere | double s1 = (-b - Math.sqrt(discriminant)) / (2 * a); "
            + "| double s1 = (-b - Math.sqrt(discriminant)) / 2 * a;",
        "Sphere | s1 > 0 ? s1 : s2 | s2 > 0 ? s1 : s2",
        "Sphere | this.radius = radius; | radius = radius;",
        "Renderer | Math.pow(Math.max(0, RdotV), n) | Math.pow(Math.max(0, NdotL), n)",
        "Renderer | double RdotV = R.dot(V); | double RdotV = V.dot(R);",
        "Renderer | Vector3 linearRGB = trace(scene, ray); | Vector3 linearRGB = trace(scene, camera.castRay(x, y));"})
    void aChangeOfMeaningIsNeverHidden(String className, String text, String replacement) throws IOException {
        String source = ours(className);
        assertThat(source).containsOnlyOnce(text);
        CliRun run = CliRun.of("diff", write(className + ".java", source.replace(text, replacement)).toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_DIFFERENT);
        assertThat(run.out()).as(run.transcript()).contains(replacement.strip());
    }

    /** A member the starter code gives whole may be the starter's version; one it leaves to write may not. */
    @Test
    void aMemberTheStarterGivesWholeMayBeTheStartersAndOneWithATodoMayNot() throws Exception {
        JavaMembers ours = JavaMembers.parse("T.java",
                "class T { int given() { return 1; } int todo() { return 2; } }");
        JavaMembers starter = JavaMembers.parse("T.java", "class T { int given() { return 3; } "
                + "int todo() { /* TODO: return 2 */ return 0; } }");
        JavaMembers theirs = JavaMembers.parse("T.java", "class T { int given() { return 3; } "
                + "int todo() { return 0; } }");
        java.util.List<String> report = DiffCommand.compare(ours, starter, theirs, Path.of("T.java"),
                new DiffCommand.Colours(false));
        assertThat(report).as(String.join("\n", report)).contains("@@ todo() @@").doesNotContain("@@ given() @@");
    }

    /** Whether the sandbox can be made here, once asked; null before. */
    private static Boolean sandboxHere;

    /**
     * Whether the sandbox, where diff runs the probes that make its hints, can be made here: asked once
     * for the class (making one runs bubblewrap's self-test), as no test of it changes what makes it.
     */
    private static synchronized boolean sandboxHere() throws InterruptedException {
        if (sandboxHere == null) {
            try {
                gfx.tick1.command.shared.grader.sandbox.Sandbox.confined();
                sandboxHere = true;
            } catch (gfx.tick1.command.shared.grader.sandbox.Sandbox.Unavailable e) {
                sandboxHere = false;
            }
        }
        return sandboxHere;
    }

    private static java.util.List<String> hints(CliRun run) {
        return run.out().lines().filter(line -> line.startsWith("hint: ") || line.startsWith("note: ")
                || line.startsWith("behaviour could not be checked: ")).toList();
    }

    /**
     * The kit's files as handed out: the two stages before any code is written, each named by the
     * model of the method the kit leaves to write (the other file is ours), in a first line, with
     * the section to reread as the one hint.
     */
    @ParameterizedTest(name = "{0}")
    @CsvSource({"Sphere, intersectionWith(Ray), intersectionWith, BACKGROUND_ONLY",
        "Renderer, 'illuminate(Scene, Sphere, Vector3, Vector3)', illuminate, FLAT_COLOUR"})
    void theUntouchedKitExitsOneAndNamesTheStageItsMethodIsAt(String className, String member, String method,
            Variant stage) throws IOException, InterruptedException {
        org.junit.jupiter.api.Assumptions.assumeTrue(sandboxHere(), "the sandbox can be made here");
        Path file = write(className + ".java", StarterKit.source(className));
        CliRun run = CliRun.of("diff", file.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_DIFFERENT);
        assertThat(run.out()).as(run.transcript()).startsWith("your " + method + " gives the answers of \""
                + stage.title() + "\" on all ").contains("@@ " + member + " @@");
        assertThat(hints(run)).as(run.transcript()).containsExactly("hint: reread handout " + stage.reread() + ".");
    }

    /** Hints rest on the answers of the code: a correct solution, however written, gets no hint and no note. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("otherCode")
    void aCorrectSolutionWrittenAnotherWayGetsNoHint(CorrectStyles.Style style)
            throws IOException, InterruptedException {
        org.junit.jupiter.api.Assumptions.assumeTrue(sandboxHere(), "the sandbox can be made here");
        CliRun run = diffOf(style);
        assertThat(hints(run)).as(run.transcript()).isEmpty();
    }

    static Stream<gfx.tick1.command.shared.behaviour.WrittenStyles.Style> writtenStyles() {
        return gfx.tick1.command.shared.behaviour.WrittenStyles.all().values().stream();
    }

    /**
     * A correct solution of a style of its own behaves as ours: nothing to fix, no hint, no note, exit 0.
     * Each style rewrites one method, intersectionWith or illuminate, in the correct solution, so one
     * diff runs two styles: the Sphere.java of one that rewrites intersectionWith with the Renderer.java
     * of one that rewrites illuminate.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("writtenStyles")
    void aCorrectSolutionOfAStyleOfItsOwnExitsZeroWithNoHintAndNoNote(WrittenStyles.Style style)
            throws IOException, InterruptedException {
        org.junit.jupiter.api.Assumptions.assumeTrue(sandboxHere(), "the sandbox can be made here");
        CliRun run = writtenPairRun(style);
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_SAME);
        assertThat(hints(run)).as(run.transcript()).isEmpty();
        assertThat(run.out().lines().findFirst()).as(run.transcript()).contains(DiffCommand.NOTHING_TO_FIX);
        assertThat(run.out().lines().skip(1).limit(2)).as(run.transcript()).allMatch(line -> line.startsWith("your ")
                && line.contains(" behaves as ours on "));
    }

    /** The diff of the written style's pair ({@link #aCorrectSolutionOfAStyleOfItsOwnExitsZeroWithNoHintAndNoNote}). */
    private static CliRun writtenPairRun(WrittenStyles.Style style) throws IOException, InterruptedException {
        String correctSphere = Files.readString(Path.of("src/test/resources/students/correct/Sphere.java"));
        java.util.List<WrittenStyles.Style> spheres = WrittenStyles.all().values().stream()
                .filter(written -> !written.sphere().equals(correctSphere)).toList();
        java.util.List<WrittenStyles.Style> renderers = WrittenStyles.all().values().stream()
                .filter(written -> written.sphere().equals(correctSphere)).toList();
        // The k-th pair: the k-th Renderer style with a Sphere style, each Sphere style in at least one pair.
        int k = spheres.contains(style) ? spheres.indexOf(style) : renderers.indexOf(style);
        WrittenStyles.Style sphere = spheres.get(k % spheres.size()), renderer = renderers.get(k % renderers.size());
        return shared("written-" + k, folder -> CliRun.of("diff",
                Files.writeString(folder.resolve("Sphere.java"), sphere.sphere()).toString(),
                Files.writeString(folder.resolve("Renderer.java"), renderer.renderer()).toString()));
    }

    @Test
    void withoutTheSandboxThereAreNoHintsAndOneLineSaysWhy() throws IOException, InterruptedException {
        CliRun run = kitRendererWithoutBubblewrap();
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_DIFFERENT);
        assertThat(hints(run)).as(run.transcript()).hasSize(1).allMatch(line -> line.startsWith(
                "behaviour could not be checked: it comes from running your methods in the sandbox"));
    }

    @Test
    void whereTheKernelRefusesNamespacesTheHintSaysSoNotThatBubblewrapIsMissing()
            throws IOException, InterruptedException {
        Path file = write("Renderer.java", StarterKit.source("Renderer"));
        // The refusing bwrap is named to a tick1 in a JVM of its own, so that no other test's sandbox is affected.
        CliRun run = CliRun.inJvm(dir, java.util.List.of("-Dtick1.grade.bwrap=" + RefusedNamespaces.bwrap(dir)),
                "diff", file.toString());
        assertThat(hints(run)).as(run.transcript()).singleElement().asString()
                .contains(RefusedNamespaces.WHAT_BWRAP_SAYS, "user namespaces").doesNotContain("install");
    }

    /** {@code tick1 diff} of the kit's Renderer.java as on a machine without bubblewrap, read by two tests. */
    private static CliRun kitRendererWithoutBubblewrap() throws IOException, InterruptedException {
        return shared("kit-renderer-without-bubblewrap", folder -> withoutBubblewrap("diff",
                Files.writeString(folder.resolve("Renderer.java"), StarterKit.source("Renderer")).toString()));
    }

    /** Runs {@code diff} with these arguments as on a machine without bubblewrap (macOS, Windows). */
    private static CliRun withoutBubblewrap(String... args) throws IOException {
        // The missing bwrap is named to a tick1 in a JVM of its own: classes that grade or diff in the
        // tests' JVM run beside this one, and would find no sandbox.
        try {
            return CliRun.inJvm(Path.of("").toAbsolutePath(),
                    java.util.List.of("-Dtick1.grade.bwrap=/nonexistent/bwrap"), args);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
    }

    @Test
    void withoutTheSandboxTheLineThatSaysBehaviourCouldNotBeCheckedNamesNoSandbox()
            throws IOException, InterruptedException {
        CliRun run = kitRendererWithoutBubblewrap();
        assertThat(hints(run)).as(run.transcript()).singleElement().asString().contains("--no-sandbox");
    }

    /**
     * The correct solution with render's progress line removed and P and N inlined in trace: starter members
     * edited, the images the same.
     */
    private static CorrectStyles.Style starterMembersEdited() {
        return new CorrectStyles.Style("starter members edited", CorrectStyles.resource("Sphere.java"),
                CorrectStyles.resource("Renderer.java"), Set.of(RENDER, TRACE))
                .renderer("            System.out.println(String.format(\"%.2f\", 100 * y / (float) (height - 1)) "
                        + "+ \"% completed\");\n", "")
                .renderer("Vector3 P = closestHit.getLocation();", "")
                .renderer("Vector3 N = closestHit.getNormal();", "")
                .renderer("return this.illuminate(scene, object, P, N);",
                        "return illuminate(scene, object, closestHit.getLocation(), closestHit.getNormal());");
    }

    @Test
    void starterMembersEditedWithoutChangingAnImageAreShownButExitZero() throws IOException, InterruptedException {
        CliRun run = sandboxedDiffOf(starterMembersEdited());
        assertThat(membersShown(run)).as(run.transcript()).containsExactlyInAnyOrder(RENDER, TRACE);
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_SAME);
    }

    @Test
    void starterMembersEditedWithoutChangingAnImageAreToldThatTheImagesWereDrawnAsOurs()
            throws IOException, InterruptedException {
        CliRun run = sandboxedDiffOf(starterMembersEdited());
        java.util.List<String> lines = run.out().lines().toList();
        assertThat(lines.get(0)).as(run.transcript()).isEqualTo(DiffCommand.NOTHING_TO_FIX_DRAWN);
        assertThat(lines).as(run.transcript()).contains(DiffCommand.DRAWN_THE_SAME).doesNotContain(
                DiffCommand.NOTHING_TO_FIX, DiffCommand.FORM_ONLY);
    }

    @Test
    void aStarterMemberEditedSoThatAnImageChangesExitsOneAndNamesTheImage() throws IOException, InterruptedException {
        org.junit.jupiter.api.Assumptions.assumeTrue(sandboxHere(), "the sandbox can be made here");
        Path[] files = starterMembersEdited().renderer(RGB, "image.setRGB(x, height - 1 - y, linearRGB.toRGB());")
                .writeTo(dir.resolve("upside-down"));
        CliRun run = CliRun.of("diff", files[0].toString(), files[1].toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_DIFFERENT);
        assertThat(run.out().lines()).as(run.transcript()).doesNotContain(DiffCommand.NOTHING_TO_FIX_DRAWN)
                .anyMatch(line -> line.startsWith("your code draws tick1.xml unlike ours: ")
                        && line.contains(" pixels differ, within pixels "));
    }

    @Test
    void withNoSandboxAWrongMethodGetsItsCounterexampleWhereThereIsNoBubblewrap()
            throws IOException, InterruptedException {
        CliRun run = farRootWithNoSandbox();
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_DIFFERENT);
        assertThat(run.out()).as(run.transcript()).startsWith("your intersectionWith gives the answers of \""
                + Variant.FAR_ROOT.title() + "\" on all ").contains("; for example, for ");
        assertThat(hints(run)).as(run.transcript()).contains("hint: reread handout " + Variant.FAR_ROOT.reread() + ".");
    }

    @Test
    void withNoSandboxACorrectSolutionBehavesAsOursWhereThereIsNoBubblewrap() throws IOException, InterruptedException {
        CliRun run = correctWithNoSandbox();
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_SAME);
        assertThat(run.out().lines().findFirst()).as(run.transcript()).hasValue(DiffCommand.NOTHING_TO_FIX);
        assertThat(run.out().lines().skip(1).limit(2)).as(run.transcript()).hasSize(2)
                .allMatch(line -> line.startsWith("your ") && line.contains(" behaves as ours on "));
    }

    @Test
    void withNoSandboxOneLineSaysTheMethodsRanUnsandboxedAndHowTheyWereLimited()
            throws IOException, InterruptedException {
        CliRun run = correctWithNoSandbox();
        assertThat(run.err().lines()).as(run.transcript()).singleElement().asString()
                .startsWith("tick1 diff: note: --no-sandbox: your methods ran without a sandbox")
                .contains("time", "heap");
    }

    /** The first written style's files, diffed with --no-sandbox where there is no bubblewrap; read by two tests. */
    private static CliRun correctWithNoSandbox() throws IOException, InterruptedException {
        WrittenStyles.Style style = WrittenStyles.all().values().iterator().next();
        return shared("correct-with-no-sandbox", folder -> withoutBubblewrap("diff", "--no-sandbox",
                Files.writeString(folder.resolve("Sphere.java"), style.sphere()).toString(),
                Files.writeString(folder.resolve("Renderer.java"), style.renderer()).toString()));
    }

    /** The correct Sphere.java taking the far root. */
    private static String farRootSphere() throws IOException {
        return Files.readString(Path.of("src/test/resources/students/correct/Sphere.java"))
                .replace("double s = s1 > 0 ? s1 : s2;", "double s = s2;");
    }

    /** The folder of {@link #farRootWithNoSandbox}'s files. */
    private static final String FAR_ROOT = "far-root-with-no-sandbox";

    /**
     * The far root's Sphere.java with the correct Renderer.java, saved plainly, diffed with --no-sandbox
     * where there is no bubblewrap; read by two tests.
     */
    private static CliRun farRootWithNoSandbox() throws IOException, InterruptedException {
        return shared(FAR_ROOT, folder -> withoutBubblewrap("diff", "--no-sandbox",
                Files.writeString(folder.resolve("Sphere.java"), farRootSphere()).toString(),
                Files.writeString(folder.resolve("Renderer.java"), Files.readString(
                        Path.of("src/test/resources/students/correct/Renderer.java"))).toString()));
    }

    /**
     * Files as a Windows editor may save them (a UTF-8 byte-order mark, CRLF line ends), in a folder whose
     * name has spaces and a letter beyond ASCII, are compared as the same files saved plainly, to the word.
     */
    @Test
    void filesSavedOnWindowsInAFolderNamedWithSpacesAndAnEAreDiffedAsThePlainOnes()
            throws IOException, InterruptedException {
        gfx.tick1.FileNames.assumeTheyCanHold("Zoë");
        String sphere = farRootSphere();
        String renderer = Files.readString(Path.of("src/test/resources/students/correct/Renderer.java"));
        CliRun asPlain = farRootWithNoSandbox();
        Path plain = styles.resolve(FAR_ROOT);
        Path windows = Files.createDirectories(dir.resolve("Tick 1 (copy) Zoë"));
        CliRun asSaved = withoutBubblewrap("diff", "--no-sandbox",
                Files.writeString(windows.resolve("Sphere.java"), savedOnWindows(sphere)).toString(),
                Files.writeString(windows.resolve("Renderer.java"), savedOnWindows(renderer)).toString());
        assertThat(asPlain.out()).as(asPlain.transcript()).contains("@@ " + INTERSECTION + " @@", "for example");
        assertThat(asSaved.status()).as(asSaved.transcript()).isEqualTo(asPlain.status());
        assertThat(asSaved.out().replace(windows.toString(), "FOLDER")).as(asSaved.transcript())
                .isEqualTo(asPlain.out().replace(plain.toString(), "FOLDER"));
    }

    /** A file as a Windows editor may save it: a UTF-8 byte-order mark, then CRLF line ends. */
    private static String savedOnWindows(String source) {
        return "\uFEFF" + source.replace("\r\n", "\n").replace("\n", "\r\n");
    }

    @Test
    void coloursAreOnOnlyOnAConsoleThatCanShowThemAndNotWithNoColourNorOnADumbTerminal() {
        java.util.Map<String, String> xterm = java.util.Map.of("TERM", "xterm-256color");
        assertThat(DiffCommand.Colours.wanted(true, xterm, true)).as("a terminal").isTrue();
        assertThat(DiffCommand.Colours.wanted(false, xterm, true)).as("output redirected").isFalse();
        assertThat(DiffCommand.Colours.wanted(true, xterm, false)).as("a console without ANSI colours").isFalse();
        assertThat(DiffCommand.Colours.wanted(true, java.util.Map.of("TERM", "xterm", "NO_COLOR", "1"), true))
                .as("NO_COLOR").isFalse();
        assertThat(DiffCommand.Colours.wanted(true, java.util.Map.of("TERM", "xterm", "NO_COLOR", ""), true))
                .as("NO_COLOR empty, which no-color.org says is not set").isTrue();
        assertThat(DiffCommand.Colours.wanted(true, java.util.Map.of("TERM", "dumb"), true)).as("TERM=dumb")
                .isFalse();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("mistakes")
    void aMistakeExitsOneNamesItsMethodAndGivesItsProbesHints(Variant mistake, String className, String method,
            String text, String replacement) throws IOException, InterruptedException {
        org.junit.jupiter.api.Assumptions.assumeTrue(sandboxHere(), "the sandbox can be made here");
        // The student's correct solution (ours is the engine's, in its own packages): it compiles with the kit.
        String source = Files.readString(Path.of("src/test/resources/students/correct/" + className + ".java"));
        assertThat(source).as("the edit's text must be in the correct " + className).containsOnlyOnce(text);
        Path file = write(className + ".java", source.replace(text, replacement));
        CliRun run = CliRun.of("diff", file.toString());
        assertThat(run.out()).as(run.transcript()).contains("@@ " + method + " @@");
        String called = className.equals("Sphere") ? "intersectionWith" : "illuminate";
        // A mistake of render's, or one that changes nothing the method returns where the course's scenes look
        // (sqrt of a negative discriminant is NaN, and NaN > 0 is false; no hit from inside, as the handout's
        // six steps), gives no hint: the method behaves as ours.
        if (method.equals(RENDER) || mistake == Variant.UNCHECKED_NEGATIVE_SQUARE_ROOT
                || mistake == Variant.HIT_REJECTED_ON_A_NEGATIVE_ROOT) {
            assertThat(hints(run)).as(run.transcript()).isEmpty();
            // Where the methods are all that differs, the first line says there is nothing to fix.
            assertThat(run.out()).as(run.transcript()).startsWith((method.equals(RENDER) ? ""
                    : DiffCommand.NOTHING_TO_FIX + System.lineSeparator()) + "your " + called + " behaves as ours on ");
            assertThat(run.status()).as(run.transcript()).isEqualTo(method.equals(RENDER) ? DiffCommand.EXIT_DIFFERENT
                    : DiffCommand.EXIT_SAME);
        } else if (mistake == null) {
            assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_DIFFERENT);
            assertThat(run.out().lines().findFirst().orElse("")).as(run.transcript())
                    .startsWith("your " + called + " differs from ours on ").contains("; the simplest: for ")
                    .endsWith("; tick1 does not recognise this mistake");
        } else {
            assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_DIFFERENT);
            assertThat(run.out()).as(run.transcript()).startsWith("your " + called + " gives the answers of \""
                    + mistake.title() + "\" on all ");
            assertThat(hints(run)).as(run.transcript())
                    .containsExactly("hint: reread handout " + mistake.reread() + ".");
        }
        assertThat(run.out()).doesNotContain("\u001B[");
    }

    @Test
    void aFileThatDoesNotParseGetsTheParsersMessageWithFileLineAndColumn() throws IOException {
        Path file = write("Sphere.java", ours("Sphere").replace("double a = D.dot(D);", "double a = D.dot(D)"));
        CliRun run = CliRun.of("diff", file.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_CANNOT_COMPARE);
        assertThat(run.err()).matches("tick1 diff: " + java.util.regex.Pattern.quote(file.toString())
                + ":\\d+:\\d+: .+\\R");
        assertThat(run.out()).isEmpty();
    }

    /** Parsing and comparing recurse through the tree: code nested thousands deep must not overflow. */
    @Test
    void codeNestedThousandsDeepIsCompared() throws IOException {
        String nested = "(".repeat(3000) + "2 * a" + ")".repeat(3000);
        Path file = write("Sphere.java", ours("Sphere").replace("double a = D.dot(D);", "double a = D.dot(D);\n"
                + "        double deep = " + nested + ";"));
        CliRun run = CliRun.of("diff", file.toString());
        assertThat(run.status()).as(run.err()).isEqualTo(DiffCommand.EXIT_DIFFERENT);
        assertThat(run.out()).contains("+    double deep = 2 * a;");
        assertThat(run.err()).isEmpty();
    }

    @Test
    void aParseErrorIsOneShortLineWithoutTheParsersListOfExpectedTokens() throws IOException {
        Path file = write("Sphere.java", ours("Sphere").replace("public class Sphere", "public class Sphere <"));
        CliRun run = CliRun.of("diff", file.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_CANNOT_COMPARE);
        assertThat(run.err()).as(run.transcript()).doesNotContain("expected one of");
        assertThat(run.err().lines()).hasSize(1);
    }

    @Test
    void aFileThatIsNotJavaIsSaidToBeSoInOneLine() throws IOException {
        CliRun run = CliRun.of("diff", "scenes/tick1.xml");
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_CANNOT_COMPARE);
        assertThat(run.err()).isEqualTo("tick1 diff: scenes/tick1.xml: not Java source; give your Sphere.java and "
                + "Renderer.java" + System.lineSeparator());
    }

    @Test
    void aFolderIsNamedAsOneAndItsTwoFilesAreSuggested() {
        CliRun run = CliRun.of("diff", "src/test/resources/students/correct");
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_CANNOT_COMPARE);
        assertThat(run.err()).isEqualTo("tick1 diff: src/test/resources/students/correct: a folder, not a file; "
                + "did you mean tick1 diff src/test/resources/students/correct/Sphere.java "
                + "src/test/resources/students/correct/Renderer.java?" + System.lineSeparator());
    }

    @Test
    void aFileNamedWithoutTheKitsSourceFolderIsFoundThere() throws IOException, InterruptedException {
        assertThat(CliRun.of("starter", "--out", dir.resolve("kit").toString()).status()).isZero();
        CliRun run = CliRun.inFolder(dir.resolve("kit"), "diff", "Sphere.java", "Renderer.java");
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_CANNOT_COMPARE);
        assertThat(run.err()).isEqualTo("tick1 diff: Sphere.java: no such file; did you mean "
                + StarterKit.SOURCE_FOLDER + "Sphere.java?" + System.lineSeparator());
    }

    @Test
    void aFileOfAnotherClassIsOneLineAndExitTwo() throws IOException {
        Path file = write("Camera.java", "package gfx.tick1; public class Camera { }");
        CliRun run = CliRun.of("diff", file.toString());
        assertThat(run.status()).as(run.transcript()).isEqualTo(DiffCommand.EXIT_CANNOT_COMPARE);
        assertThat(run.err()).isEqualTo("tick1 diff: " + file + ": class Camera: expected Sphere or Renderer, the "
                + "two classes of the tick" + System.lineSeparator());
    }

    /** On a terminal the removed lines are red, the added green; captured output has no colour at all. */
    @Test
    void colourIsForTerminalsOnly() throws Exception {
        JavaMembers ours = ReferenceMembers.ours("Sphere");
        JavaMembers theirs = JavaMembers.parse("Sphere.java",
                ours("Sphere").replace("double s = s1 > 0 ? s1 : s2;", "double s = s2;"));
        java.util.List<String> coloured = DiffCommand.compare(ours, null, theirs, Path.of("Sphere.java"),
                new DiffCommand.Colours(true));
        assertThat(coloured).contains("\u001B[31m-    double s = s1 > 0 ? s1 : s2;\u001B[0m",
                "\u001B[32m+    double s = s2;\u001B[0m");
        assertThat(DiffCommand.compare(ours, null, theirs, Path.of("Sphere.java"), new DiffCommand.Colours(false)))
                .noneMatch(line -> line.contains("\u001B"));
    }
}
