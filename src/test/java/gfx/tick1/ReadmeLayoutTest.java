package gfx.tick1;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The README is for the people who use tick1, in at most 150 lines: its set-up, then students, then
 * course staff. The documentation in docs/ says what they need in at most 18,000 words, each page
 * opening with what its reader does with it, and every relative link of the pages reaches a file
 * and heading that exist. CONTRIBUTING.md's "Source layout" and the documentation name the tree as
 * it is. The layout's block is a tree: a line
 * whose first words are paths ({@code engine/}, {@code Tick1.java}, {@code compare/ diff/}) names them inside the
 * nearest folder above it that is indented less; any other line goes on describing the line before. Every path of
 * it exists, and every package of the program has its line. Elsewhere (README.md, CONTRIBUTING.md, docs/*.md), a
 * source path in code or in a link exists: one from the project's folder ({@code src/main/...}, {@code scenes/...})
 * or one whose first folder is a package folder of the program, read from {@code src/main/java/gfx/tick1}
 * ({@code engine/render/Renderer}, {@code command/shared/grader/harness/}), with or without {@code .java}. Every
 * class the layout's section names exists, and every test selection shown ({@code -Ptests=}, {@code --tests})
 * names a test package, class or method.
 */
class ReadmeLayoutTest {

    private static final Path SOURCES = Path.of("src/main/java/gfx/tick1");
    private static final Path TESTS = Path.of("src/test/java");
    /** The beginnings of a path read from the project's folder. */
    private static final List<String> FROM_THE_PROJECT = List.of("src/main/", "src/test/", "scenes/",
            "reference-images/", "config/", "docs/", ".ci/");
    private static final Pattern CODE = Pattern.compile("`([^`\\s]+)`");
    private static final Pattern LINK = Pattern.compile("\\]\\(([^)\\s]+)\\)");
    private static final Pattern TEST_SELECTION = Pattern.compile("(?:-Ptests=|--tests )('[^']+'|\\S+)");

    private static List<Path> pages() throws IOException {
        List<Path> pages = new ArrayList<>(List.of(Path.of("README.md"), Path.of("CONTRIBUTING.md")));
        pages.addAll(docsPages());
        return pages;
    }

    /** CONTRIBUTING.md from its section "Source layout" up to the next section. */
    private static String layoutSection() throws IOException {
        String contributing = Files.readString(Path.of("CONTRIBUTING.md"));
        String section = contributing.substring(contributing.indexOf("## Source layout"));
        int next = section.indexOf("\n## ", 1);
        return next < 0 ? section : section.substring(0, next);
    }

    /** A folder of the layout's tree and how far its line is indented. */
    private record Folder(int indent, String path) {
    }

    /** Every path the layout's block names, from the project's folder (a folder ends with "/"). */
    static List<String> layoutPaths() throws IOException {
        String section = layoutSection();
        String block = section.substring(section.indexOf("```\n") + 4);
        block = block.substring(0, block.indexOf("```"));
        List<String> paths = new ArrayList<>();
        Deque<Folder> folders = new ArrayDeque<>();
        for (String line : block.lines().toList()) {
            List<String> names = leadingPaths(line.strip());
            if (names.isEmpty()) {
                continue;
            }
            int indent = line.length() - line.stripLeading().length();
            while (!folders.isEmpty() && folders.peek().indent() >= indent) {
                folders.pop();
            }
            String parent = folders.isEmpty() ? "" : folders.peek().path();
            names.forEach(name -> paths.add(parent + name));
            if (names.size() == 1 && names.get(0).endsWith("/")) {
                folders.push(new Folder(indent, parent + names.get(0)));
            }
        }
        return paths;
    }

    /** The words a line starts with that are paths: each ends with "/" or ".java", or holds a "/". */
    private static List<String> leadingPaths(String line) {
        List<String> names = new ArrayList<>();
        for (String word : line.split("\\s+")) {
            String name = word.endsWith(",") ? word.substring(0, word.length() - 1) : word;
            if (name.isEmpty() || !(name.endsWith("/") || name.endsWith(".java") || name.contains("/"))) {
                break;
            }
            names.add(name);
        }
        return names;
    }

    @Test
    void everyPathOfTheSourceLayoutExists() throws IOException {
        List<String> paths = layoutPaths();

        assertThat(paths).as("the paths of CONTRIBUTING.md's source layout").contains("src/main/java/gfx/tick1/")
                .allSatisfy(path -> assertThat(Path.of(path)).as("%s, in CONTRIBUTING.md's source layout", path)
                        .exists());
    }

    @Test
    void everyPackageOfTheProgramHasItsLineInTheSourceLayout() throws IOException {
        List<String> layout = layoutPaths();
        List<String> missing;
        try (Stream<Path> tree = Files.walk(SOURCES)) {
            missing = tree.filter(Files::isDirectory).filter(folder -> !folder.equals(SOURCES))
                    .map(folder -> folder.toString().replace('\\', '/') + "/")
                    .filter(folder -> !layout.contains(folder)).sorted().toList();
        }

        assertThat(missing).as("the package folders CONTRIBUTING.md's source layout leaves out").isEmpty();
    }

    /** The folder names of the program's packages, at any depth: "engine", "scene", "grader", ... */
    private static Set<String> packageFolderNames() throws IOException {
        try (Stream<Path> tree = Files.walk(SOURCES)) {
            return tree.filter(Files::isDirectory).filter(folder -> !folder.equals(SOURCES))
                    .map(folder -> folder.getFileName().toString()).collect(Collectors.toCollection(TreeSet::new));
        }
    }

    /** The source paths a page names in code or links to, each with the page and line that name it. */
    static List<String[]> namedSourcePaths() throws IOException {
        Set<String> packageFolders = packageFolderNames();
        List<String[]> named = new ArrayList<>();
        for (Path page : pages()) {
            List<String> lines = Files.readAllLines(page);
            for (int i = 0; i < lines.size(); i++) {
                for (Pattern pattern : List.of(CODE, LINK)) {
                    Matcher matcher = pattern.matcher(lines.get(i));
                    while (matcher.find()) {
                        String path = matcher.group(1).replaceFirst("[<#].*$", "");
                        String first = path.contains("/") ? path.substring(0, path.indexOf('/')) : "";
                        if (FROM_THE_PROJECT.stream().anyMatch(path::startsWith)) {
                            named.add(new String[] {page + ":" + (i + 1), path});
                        } else if (packageFolders.contains(first)) {
                            named.add(new String[] {page + ":" + (i + 1), SOURCES + "/" + path});
                        }
                    }
                }
            }
        }
        return named;
    }

    /** Whether {@code path} is a file or folder, or a class without its ".java", or a glob in its last name. */
    private static boolean exists(String path) throws IOException {
        if (Files.exists(Path.of(path)) || Files.exists(Path.of(path + ".java"))) {
            return true;
        }
        Path asPath = Path.of(path);
        if (!asPath.getFileName().toString().contains("*") || !Files.isDirectory(asPath.getParent())) {
            return false;
        }
        try (DirectoryStream<Path> matches = Files.newDirectoryStream(asPath.getParent(),
                asPath.getFileName().toString())) {
            return matches.iterator().hasNext();
        }
    }

    @Test
    void everySourcePathTheDocumentationNamesExists() throws IOException {
        List<String> missing = new ArrayList<>();
        List<String[]> named = namedSourcePaths();
        for (String[] place : named) {
            if (!exists(place[1])) {
                missing.add(place[0] + ": " + place[1]);
            }
        }

        assertThat(named).as("the source paths the pages name").hasSizeGreaterThan(20);
        assertThat(missing).as("source paths named in README.md, CONTRIBUTING.md or docs/*.md that do not exist")
                .isEmpty();
    }

    @Test
    void everyClassTheSourceLayoutSectionNamesExists() throws IOException {
        Set<String> classes;
        try (Stream<Path> files = Stream.concat(Files.walk(Path.of("src/main/java")), Files.walk(TESTS))) {
            classes = files.map(file -> file.getFileName().toString()).filter(name -> name.endsWith(".java"))
                    .map(name -> name.substring(0, name.length() - ".java".length())).collect(Collectors.toSet());
        }
        List<String> named = new ArrayList<>();
        Matcher matcher = CODE.matcher(layoutSection());
        while (matcher.find()) {
            if (matcher.group(1).matches("[A-Z][A-Za-z0-9]*")) {
                named.add(matcher.group(1));
            }
        }

        assertThat(named).as("the classes CONTRIBUTING.md's source layout section names").isNotEmpty()
                .allSatisfy(name -> assertThat(classes).as("the classes of src/main and src/test").contains(name));
    }

    @Test
    void everyTestSelectionShownNamesATestPackageClassOrMethod() throws IOException {
        List<String> shown = new ArrayList<>();
        for (Path page : pages()) {
            Matcher matcher = TEST_SELECTION.matcher(Files.readString(page));
            while (matcher.find()) {
                for (String selection : matcher.group(1).replace("'", "").split(",")) {
                    shown.add(selection.replaceFirst("\\.\\*$", ""));
                }
            }
        }

        assertThat(shown).as("the test selections the pages show").isNotEmpty()
                .allSatisfy(selection -> assertThat(selects(selection)).as(selection).isTrue());
    }

    /** Whether a test package, a test class or a test class's method has the name {@code selection}. */
    private static boolean selects(String selection) throws IOException {
        Path path = TESTS.resolve(selection.replace('.', '/'));
        if (Files.isDirectory(path) || Files.isRegularFile(Path.of(path + ".java"))) {
            return true;
        }
        Path testClass = Path.of(path.getParent() + ".java");
        return Files.isRegularFile(testClass)
                && Files.readString(testClass).contains(" " + path.getFileName() + "(");
    }

    /** The documentation's pages: docs/*.md. */
    private static List<Path> docsPages() throws IOException {
        List<Path> pages = new ArrayList<>();
        try (DirectoryStream<Path> docs = Files.newDirectoryStream(Path.of("docs"), "*.md")) {
            docs.forEach(pages::add);
        }
        return pages;
    }

    @Test
    void theReadmeIsAtMost150Lines() throws IOException {
        assertThat(Files.readAllLines(Path.of("README.md"))).as("README.md's lines").hasSizeLessThanOrEqualTo(150);
    }

    @Test
    void theReadmeGivesTheSetUpThenTheStudentsSectionThenTheStaffs() throws IOException {
        List<String> sections = Files.readAllLines(Path.of("README.md")).stream()
                .filter(line -> line.startsWith("## ")).toList();

        assertThat(sections).as("README.md's sections").startsWith("## Build and render", "## For students",
                "## For course staff");
    }

    @Test
    void theStudentsSectionStartsFromTheStudentsJar() throws IOException {
        String readme = Files.readString(Path.of("README.md"));
        String section = readme.substring(readme.indexOf("## For students") + "## For students".length()).strip();

        assertThat(section).as("the README's section for students").startsWith("Download `tick1.jar` from Moodle")
                .contains("`java -jar tick1.jar ...`");
    }

    /** Words as {@code wc -w} counts them: runs of anything but white space. */
    @Test
    void theDocumentationIsAtMost18000Words() throws IOException {
        long words = 0;
        for (Path page : docsPages()) {
            words += Arrays.stream(Files.readString(page).split("\\s+")).filter(word -> !word.isEmpty()).count();
        }

        assertThat(words).as("the words of docs/*.md").isPositive().isLessThanOrEqualTo(18_000);
    }

    /**
     * Under its title, a page first says in a sentence or two what its reader does with it: a short paragraph of
     * prose, not a table, list, code block or heading.
     */
    @Test
    void everyDocumentationPageOpensWithASentenceOrTwoOfWhatItIsFor() throws IOException {
        for (Path page : docsPages()) {
            List<String> lines = Files.readAllLines(page);
            assertThat(lines.get(0)).as("%s's first line", page).startsWith("# ");
            String opening = lines.stream().skip(1).dropWhile(String::isBlank).takeWhile(line -> !line.isBlank())
                    .collect(Collectors.joining(" "));

            assertThat(opening).as("%s's opening paragraph", page).doesNotStartWithIgnoringCase("|")
                    .matches("[A-Za-z`*].*\\.").satisfies(text -> assertThat(text.split("\\s+"))
                            .as("the words of %s's opening paragraph", page).hasSizeLessThanOrEqualTo(60));
        }
    }

    /** The anchors GitHub gives a page's headings: lower case, punctuation dropped, spaces made hyphens. */
    private static Set<String> anchors(Path page) throws IOException {
        Set<String> anchors = new TreeSet<>();
        boolean inBlock = false;
        for (String line : Files.readAllLines(page)) {
            if (line.startsWith("```")) {
                inBlock = !inBlock;
            } else if (!inBlock && line.matches("#{1,6} .*")) {
                String slug = line.replaceFirst("^#+ ", "").strip().toLowerCase(Locale.ROOT)
                        .replaceAll("[^\\p{L}\\p{N} _-]", "").replace(' ', '-');
                String anchor = slug;
                for (int n = 1; anchors.contains(anchor); n++) {
                    anchor = slug + "-" + n;
                }
                anchors.add(anchor);
            }
        }
        return anchors;
    }

    @Test
    void everyRelativeLinkOfThePagesReachesAFileAndHeadingThatExist() throws IOException {
        List<String> broken = new ArrayList<>();
        int links = 0;
        for (Path page : pages()) {
            List<String> lines = Files.readAllLines(page);
            for (int i = 0; i < lines.size(); i++) {
                Matcher matcher = LINK.matcher(lines.get(i));
                while (matcher.find()) {
                    String target = matcher.group(1);
                    if (target.matches("[a-z]+:.*")) {
                        continue;
                    }
                    links++;
                    String file = target.replaceFirst("#.*$", "");
                    Path linked = file.isEmpty() ? page : page.resolveSibling(file).normalize();
                    String anchor = target.contains("#") ? target.substring(target.indexOf('#') + 1) : "";
                    boolean headingFound = anchor.isEmpty()
                            || linked.toString().endsWith(".md") && Files.isRegularFile(linked)
                            && anchors(linked).contains(anchor);
                    if (!Files.exists(linked) || linked.startsWith("..") || !headingFound) {
                        broken.add(page + ":" + (i + 1) + ": " + target);
                    }
                }
            }
        }

        assertThat(links).as("the relative links of the pages").isGreaterThan(20);
        assertThat(broken).as("relative links of README.md, CONTRIBUTING.md or docs/*.md that reach nothing").isEmpty();
    }
}
