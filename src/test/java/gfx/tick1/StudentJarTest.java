package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;

import gfx.tick1.command.shared.behaviour.WrittenStyles;
import gfx.tick1.engine.image.PngOutput;
import gfx.tick1.engine.render.ReferenceRenderer;
import gfx.tick1.engine.scene.BundledScenes;
import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Duration;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The students' release, build/libs/tick1.jar, run as {@code java -jar tick1.jar ...} on a machine
 * that has Java and nothing else: a root file system made with bubblewrap that holds only the JDK,
 * the libraries it loads and the student's folder, with no shell, no /usr/bin and so no bubblewrap.
 * Every command a student uses gives its right answer there; the student's folder is named with a
 * space and a letter beyond ASCII, as {@code C:\Users\Zoë\Tick 1} would be. The Gradle build makes
 * the jar before the tests and names it in the system property {@value #JAR_PROPERTY}.
 */
class StudentJarTest {

    static final String JAR_PROPERTY = "tick1.studentJar";
    /** The student's folder, as the bare root shows it. */
    private static final String HOME = "/home/Zoë/Tick 1";
    private static final String JAR = HOME + "/tick1.jar";
    /** The same jar, bound where its name is ASCII. */
    private static final String ASCII_JAR = "/opt/tick1.jar";
    private static final Duration RUN_LIMIT = Duration.ofMinutes(5);
    private static final Path LOCALE = Path.of("/usr/lib/locale/C.utf8");

    /** The arguments that make the bare root, up to the student's folder; null until {@link #bareRootHere}. */
    private static List<String> bareRoot;

    /** The student's folder on this side. */
    @TempDir
    Path home;

    /** What each run printed, beside the student's folder. */
    @TempDir
    Path printed;

    @BeforeAll
    static void bareRootHere() throws IOException, InterruptedException {
        FileNames.assumeTheyCanHold(HOME);
        String jar = System.getProperty(JAR_PROPERTY);
        Assumptions.assumeTrue(jar != null && Files.isRegularFile(Path.of(jar)),
                "the students' jar is not built (gradle studentJar), or " + JAR_PROPERTY + " does not name it");
        Path bwrap = Path.of("/usr/bin/bwrap");
        Assumptions.assumeTrue(Files.isExecutable(bwrap) && Files.isExecutable(Path.of("/usr/bin/ldd")),
                "bubblewrap (and ldd) are needed to make a bare root, and are not installed");
        Process check = new ProcessBuilder(bwrap.toString(), "--unshare-all", "--ro-bind", "/", "/", "/bin/true")
                .redirectErrorStream(true).start();
        String said = new String(check.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
        Assumptions.assumeTrue(check.waitFor() == 0, "bubblewrap cannot make namespaces here: " + said);
        bareRoot = bareRootArguments(bwrap);
    }

    @BeforeEach
    void studentsFolder() throws IOException {
        Files.copy(Path.of(System.getProperty(JAR_PROPERTY)), home.resolve("tick1.jar"));
    }

    /**
     * bwrap's arguments for a root that holds the JDK (by its real path, and the files of its links
     * that lead out of it, Debian's configuration in /etc), the libraries that ldd says its programs
     * and libraries load, /proc, /dev and an empty /tmp; in UTF-8 (with glibc's files for it), as a
     * student's desktop is.
     */
    private static List<String> bareRootArguments(Path bwrap) throws IOException, InterruptedException {
        Path jdk = Path.of(System.getProperty("java.home")).toRealPath();
        Set<Path> files = new LinkedHashSet<>();
        List<Path> binaries = new ArrayList<>();
        try (Stream<Path> all = Files.walk(jdk)) {
            for (Path path : all.toList()) {
                if (Files.isSymbolicLink(path)) {
                    Path target = path.getParent().resolve(Files.readSymbolicLink(path)).normalize();
                    if (!target.startsWith(jdk) && Files.isRegularFile(target)) {
                        files.add(target);
                    }
                } else if (Files.isRegularFile(path) && (path.toString().endsWith(".so")
                        || path.getParent().getFileName().toString().equals("bin"))) {
                    binaries.add(path);
                }
            }
        }
        Pattern library = Pattern.compile("(?:=>\\s*)?(/\\S+)\\s+\\(0x");
        for (Path binary : binaries) {
            Process ldd = new ProcessBuilder("/usr/bin/ldd", binary.toString()).redirectErrorStream(true).start();
            String listed = new String(ldd.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            ldd.waitFor();
            Matcher loaded = library.matcher(listed);
            while (loaded.find()) {
                Path file = Path.of(loaded.group(1));
                if (!file.startsWith(jdk) && Files.exists(file)) {
                    files.add(file);
                }
            }
        }
        List<String> arguments = new ArrayList<>(List.of(bwrap.toString(), "--unshare-all", "--share-net",
                "--die-with-parent", "--clearenv", "--setenv", "LANG", "C.UTF-8", "--setenv", "HOME", "/home/Zoë",
                "--proc", "/proc", "--dev", "/dev", "--tmpfs", "/tmp", "--ro-bind", jdk.toString(), jdk.toString()));
        for (Path file : files) {
            arguments.addAll(List.of("--ro-bind", file.toString(), file.toString()));
        }
        // The locale's files, where glibc keeps C.UTF-8 in files (before 2.35; Debian's still does): without
        // them Java would take file names as ASCII, as no student's desktop does.
        if (Files.isDirectory(LOCALE)) {
            arguments.addAll(List.of("--ro-bind", LOCALE.toString(), LOCALE.toString()));
        }
        return arguments;
    }

    /** One run of {@code java -jar tick1.jar args} in the bare root, in the student's folder {@code folder} there. */
    private CliRun run(String folder, String... args) throws IOException, InterruptedException {
        return runIn("C.UTF-8", JAR, folder, args);
    }

    /** As {@link #run}, with LANG set to this locale and the jar named as given. */
    private CliRun runIn(String locale, String jar, String folder, String... args)
            throws IOException, InterruptedException {
        Process process = start(locale, jar, folder, args);
        if (!process.waitFor(RUN_LIMIT.toSeconds(), TimeUnit.SECONDS)) {
            process.destroyForcibly().waitFor();
        }
        return new CliRun(process.exitValue(), Files.readString(out()), Files.readString(err()), new byte[0]);
    }

    private Path out() {
        return printed.resolve("out.txt");
    }

    private Path err() {
        return printed.resolve("err.txt");
    }

    private Process start(String locale, String jar, String folder, String... args) throws IOException {
        List<String> command = new ArrayList<>(bareRoot);
        command.addAll(List.of("--setenv", "LANG", locale, "--bind", home.toString(), HOME, "--ro-bind",
                home.resolve("tick1.jar").toString(), ASCII_JAR, "--chdir", folder, "--",
                Path.of(System.getProperty("java.home")).toRealPath().resolve("bin/java").toString(),
                "-jar", jar));
        command.addAll(List.of(args));
        return new ProcessBuilder(command).redirectInput(ProcessBuilder.Redirect.from(new java.io.File("/dev/null")))
                .redirectOutput(out().toFile()).redirectError(err().toFile()).start();
    }

    /** Copies a file of this project into the student's folder. */
    private void give(String file, String as) throws IOException {
        Files.createDirectories(home.resolve(as).getParent());
        Files.copy(Path.of(file), home.resolve(as), StandardCopyOption.REPLACE_EXISTING);
    }

    @Test
    void withNoArgumentsInAnEmptyFolderItSaysToBeginWithTheStarterKitAsTheJarIsRun()
            throws IOException, InterruptedException {
        CliRun run = run(HOME);
        assertThat(run.status()).as(run.transcript()).isEqualTo(1);
        assertThat(run.err().lines()).as(run.transcript()).singleElement().asString()
                .contains("java -jar \"" + JAR + "\" starter writes the starter kit");
    }

    @Test
    void inALocaleThatLosesTheFoldersLettersItStopsInOneLineSayingHowToStart()
            throws IOException, InterruptedException {
        give("scenes/basic_scene.xml", "basic_scene.xml");
        // The jar in a folder of ASCII name: from a folder whose name the locale cannot read, Java itself
        // cannot open a jar there, by any name, before tick1 starts.
        CliRun run = runIn("C", ASCII_JAR, HOME, "-i", "basic_scene.xml", "-o", "ours.png");
        assertThat(run.status()).as(run.transcript()).isEqualTo(2);
        assertThat(run.err().lines()).as(run.transcript()).singleElement().asString()
                .contains("the current folder's name has letters that Java cannot read", "LC_ALL=C.UTF-8 java -jar");
        assertThat(home.resolve("ours.png")).as("nothing written, here or beside").doesNotExist();
    }

    @Test
    void versionSaysTheBuildsVersion() throws IOException, InterruptedException {
        CliRun run = run(HOME, "--version");
        assertThat(run.status()).as(run.transcript()).isZero();
        assertThat(run.out()).as(run.transcript()).startsWith("tick1 ").doesNotContain("development build");
    }

    @Test
    void starterWritesTheKitAndItsSceneRendersThere() throws IOException, InterruptedException {
        CliRun starter = run(HOME, "starter");
        assertThat(starter.status()).as(starter.transcript()).isZero();
        assertThat(home.resolve("tick1/src/gfx/tick1/Sphere.java")).isRegularFile();
        CliRun render = run(HOME + "/tick1");
        assertThat(render.status()).as(render.transcript()).isZero();
        assertThat(home.resolve("tick1/output.png")).isRegularFile();
    }

    @Test
    void renderMakesTheReferenceImageAndCompareSaysSo() throws IOException, InterruptedException {
        give("scenes/tick1.xml", "scenes/tick1.xml");
        give("reference-images/tick1.png", "expected ë.png");
        CliRun render = run(HOME, "-i", "scenes/tick1.xml", "-o", "mine ë.png");
        assertThat(render.status()).as(render.transcript()).isZero();
        CliRun compare = run(HOME, "compare", "mine ë.png", "expected ë.png");
        assertThat(compare.status()).as(compare.transcript()).isZero();
        assertThat(pixels(home.resolve("mine ë.png"))).as("the image, pixel for pixel")
                .isEqualTo(pixels(Path.of("reference-images/tick1.png")));
    }

    private static int[] pixels(Path png) throws IOException {
        java.awt.image.BufferedImage image = javax.imageio.ImageIO.read(png.toFile());
        return image.getRGB(0, 0, image.getWidth(), image.getHeight(), null, 0, image.getWidth());
    }

    /**
     * A correct render of tick1.xml, small: diagnose renders its catalogue at the image's size, and which image it
     * is, not how big, is what the jar must recognise.
     */
    @Test
    void diagnoseRecognisesACorrectRender() throws IOException, InterruptedException {
        PngOutput.write(new ReferenceRenderer(160, 120).render(BundledScenes.load(BundledScenes.TICK1)),
                home.resolve("tick1.png"));
        CliRun run = run(HOME, "diagnose", "tick1.png");
        assertThat(run.status()).as(run.transcript()).isZero();
    }

    private void writeStudent(String folder, String sphere, String renderer) throws IOException {
        Files.createDirectories(home.resolve(folder));
        Files.writeString(home.resolve(folder + "/Sphere.java"), sphere);
        Files.writeString(home.resolve(folder + "/Renderer.java"), renderer);
    }

    private static String correct(String className) throws IOException {
        return Files.readString(Path.of("src/test/resources/students/correct/" + className + ".java"));
    }

    @Test
    void diffWithNoSandboxGivesAWrongMethodItsCounterexample() throws IOException, InterruptedException {
        writeStudent("src", correct("Sphere").replace("double s = s1 > 0 ? s1 : s2;", "double s = s2;"),
                correct("Renderer"));
        CliRun run = run(HOME, "diff", "--no-sandbox", "src/Sphere.java", "src/Renderer.java");
        assertThat(run.status()).as(run.transcript()).isEqualTo(1);
        assertThat(run.out()).as(run.transcript()).startsWith("your intersectionWith gives the answers of ")
                .contains("; for example, for the ray ");
        assertThat(run.err()).as(run.transcript()).startsWith("tick1 diff: note: --no-sandbox: ");
    }

    @Test
    void diffWithNoSandboxSaysACorrectSolutionBehavesAsOurs() throws IOException, InterruptedException {
        WrittenStyles.Style style = WrittenStyles.all().values().iterator().next();
        writeStudent("src", style.sphere(), style.renderer());
        CliRun run = run(HOME, "diff", "--no-sandbox", "src/Sphere.java", "src/Renderer.java");
        assertThat(run.status()).as(run.transcript()).isZero();
        assertThat(run.out().lines().findFirst()).as(run.transcript()).hasValueSatisfying(line -> assertThat(line)
                .startsWith("Nothing to fix: "));
        assertThat(run.out().lines().skip(1).limit(2)).as(run.transcript()).hasSize(2)
                .allMatch(line -> line.startsWith("your ") && line.contains(" behaves as ours on "));
    }

    @Test
    void gradeWithNoSandboxPassesACorrectSolution() throws IOException, InterruptedException {
        writeStudent("src", correct("Sphere"), correct("Renderer"));
        CliRun run = run(HOME, "grade", "--no-sandbox", "--sphere", "src/Sphere.java", "--renderer",
                "src/Renderer.java", "--width", "160", "--height", "120");
        assertThat(run.status()).as(run.transcript()).isZero();
        assertThat(run.out()).as(run.transcript()).contains("tick1.xml: PASS", "hidden.xml: PASS");
    }

    @Test
    void gradeWithoutTheOptionRefusesInOneLineThatNamesIt() throws IOException, InterruptedException {
        writeStudent("src", correct("Sphere"), correct("Renderer"));
        CliRun run = run(HOME, "grade", "--sphere", "src/Sphere.java", "--renderer", "src/Renderer.java");
        assertThat(run.status()).as(run.transcript()).isEqualTo(2);
        assertThat(run.err().lines()).as(run.transcript()).singleElement().asString().contains("--no-sandbox");
    }

    /** The previewer serves its page, and every module the page imports, from the jar alone. */
    @Test
    void previewServesThePageAndEveryModuleItImports() throws IOException, InterruptedException {
        give("scenes/tick1.xml", "tick1.xml");
        Process preview = start("C.UTF-8", JAR, HOME, "preview", "--no-open", "--port", "0", "tick1.xml");
        try {
            URI page = null;
            for (long deadline = System.nanoTime() + RUN_LIMIT.toNanos(); page == null && preview.isAlive()
                    && System.nanoTime() < deadline; Thread.sleep(100)) {
                Matcher address = Pattern.compile("http://127\\.0\\.0\\.1:\\d+/").matcher(Files.readString(out()));
                page = address.find() ? URI.create(address.group()) : null;
            }
            assertThat(page).as("the address the previewer prints; it said: %s %s", Files.readString(out()),
                    Files.readString(err())).isNotNull();
            Map<String, String> served = fetchWithImports(page);
            assertThat(served.get("/")).as("the page").contains("<script type=\"importmap\">");
            assertThat(served.keySet()).as("what the page loads").contains("/preview.js",
                    "/three/build/three.module.min.js", "/three/build/three.core.min.js",
                    "/three/examples/jsm/controls/OrbitControls.js");
        } finally {
            preview.destroyForcibly().waitFor();
        }
    }

    /**
     * The page at {@code page} and every module it loads, fetched as a browser would: preview.js, and
     * each module's imports, bare ones through the page's import map and relative ones beside the
     * module. Each must be there (200); their texts by path.
     */
    private static Map<String, String> fetchWithImports(URI page) throws IOException, InterruptedException {
        HttpClient client = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();
        Map<String, String> served = new LinkedHashMap<>();
        String html = fetch(client, page, "/");
        served.put("/", html);
        Map<String, String> importMap = new LinkedHashMap<>();
        Matcher map = Pattern.compile("<script type=\"importmap\">(.*?)</script>", Pattern.DOTALL).matcher(html);
        assertThat(map.find()).as("the page's import map").isTrue();
        Matcher entry = Pattern.compile("\"([^\"]+)\"\\s*:\\s*\"([^\"]+)\"").matcher(map.group(1));
        while (entry.find()) {
            if (!entry.group(1).equals("imports")) {
                importMap.put(entry.group(1), entry.group(2));
            }
        }
        Deque<String> toFetch = new ArrayDeque<>(List.of("/preview.js"));
        Pattern imports = Pattern.compile("(?:\\bfrom|\\bimport)\\s*['\"]([^'\"]+)['\"]");
        while (!toFetch.isEmpty()) {
            String path = toFetch.pop();
            if (served.containsKey(path)) {
                continue;
            }
            String text = fetch(client, page, path);
            served.put(path, text);
            Matcher imported = imports.matcher(text);
            while (imported.find()) {
                toFetch.add(resolve(imported.group(1), path, importMap));
            }
        }
        return served;
    }

    private static String resolve(String specifier, String from, Map<String, String> importMap) {
        if (specifier.startsWith("./") || specifier.startsWith("../")) {
            return URI.create(from).resolve(specifier).getPath();
        }
        if (importMap.containsKey(specifier)) {
            return importMap.get(specifier);
        }
        return importMap.entrySet().stream().filter(e -> e.getKey().endsWith("/") && specifier.startsWith(e.getKey()))
                .map(e -> e.getValue() + specifier.substring(e.getKey().length())).findFirst()
                .orElseThrow(() -> new AssertionError(from + " imports " + specifier + ", which the import map "
                        + "does not resolve"));
    }

    private static String fetch(HttpClient client, URI page, String path) throws IOException, InterruptedException {
        HttpResponse<String> response = client.send(HttpRequest.newBuilder(page.resolve(path))
                .timeout(Duration.ofSeconds(30)).build(), HttpResponse.BodyHandlers.ofString());
        assertThat(response.statusCode()).as("GET " + path).isEqualTo(200);
        return response.body();
    }

}
