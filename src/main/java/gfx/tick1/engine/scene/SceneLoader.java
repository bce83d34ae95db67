package gfx.tick1.engine.scene;

import gfx.tick1.engine.io.BoundedFile;
import gfx.tick1.engine.io.IoErrors;
import gfx.tick1.engine.math.Vector3;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.xml.sax.SAXParseException;

/**
 * Reads a Tick 1 scene file: {@code <scene>} holding {@code sphere}, {@code ambient-light} and
 * {@code point-light} elements, read in document order at any depth.
 *
 * <p>Defaults are the starter code's (x, y, z = 0; radius = 1; intensity = 100; no ambient-light
 * means white ambient light; of several point lights the last is kept). Where the starter code
 * silently used a default for an unparsable number, or crashed on a bad colour, this loader
 * rejects the file with one line naming the file, line and column, and what it expected.
 *
 * <p>The file is read into a DOM {@link Document} ({@link SceneDocument}), whose elements carry
 * their line and column, and the scene is built by walking that tree's elements in document
 * order. The parser refuses any DOCTYPE, which closes off external entities and entity-expansion
 * bombs at once (OWASP's XXE advice for the JDK).
 */
public final class SceneLoader {

    /** Files larger than this are refused before parsing. */
    public static final long MAX_FILE_BYTES = 64L * 1024 * 1024;
    /**
     * Scenes with more elements than this are refused rather than exhausting memory: with the 64 MiB
     * file limit, every legal scene loads in a 1 GiB heap, Java's default on a machine with 4 GiB of
     * memory (SceneLoaderMemoryTest holds it; docs/hostile-input.md gives the peaks). Tick 1's scenes
     * have a handful of spheres; the benchmark's largest crowd has 10,000.
     */
    public static final int MAX_ELEMENTS = 250_000;
    /**
     * At most this many warnings are kept; the rest are counted in one last line, so that a
     * hostile file of many thousands of nested elements cannot fill the terminal with them.
     */
    public static final int MAX_WARNINGS = 100;
    /** The largest magnitude accepted for any coordinate, radius or intensity. */
    public static final double MAX_MAGNITUDE = 1e16;

    /** The root element of every scene file. */
    static final String ROOT = "scene";
    /** The elements inside {@code <scene>}, each with the attributes it may have. */
    static final Map<String, Set<String>> ATTRIBUTES = Map.of(
            "sphere", Set.of("x", "y", "z", "radius", "colour"),
            "point-light", Set.of("x", "y", "z", "colour", "intensity"),
            "ambient-light", Set.of("colour"));
    /** The value an attribute left out takes (colour has none: it must be given). */
    static final Map<String, Double> DEFAULTS = Map.of("x", 0.0, "y", 0.0, "z", 0.0, "radius", 1.0, "intensity", 100.0);

    // A plain decimal number as people write it in a scene file. Java's own parser would also
    // take "NaN", "0x1p3", "1d" and "Infinity", none of which belongs in a scene. The quantifiers
    // are possessive (never give back what they matched): with ordinary ones, \d+\.?\d* tries
    // every split of a long run of digits before failing, quadratic time on a hostile file.
    private static final Pattern DECIMAL = Pattern.compile("[+-]?+(\\d++\\.?+\\d*+|\\.\\d++)([eE][+-]?+\\d++)?+");
    private static final Pattern NON_FINITE = Pattern.compile("[+-]?(nan|inf|infinity)", Pattern.CASE_INSENSITIVE);
    private static final Pattern COLOUR = Pattern.compile("#[0-9A-Fa-f]{6}");

    private final String fileName;
    private final boolean strict;
    private final Scene scene = new Scene();
    private final List<String> warnings = new ArrayList<>();
    private int warningsLeftOut;

    /** The starter code's constructor: loads the file or throws {@link SceneException}. */
    public SceneLoader(String filename) {
        this(toPath(filename), false);
    }

    /** Loads {@code file}; with {@code strict}, anything that would be a warning is an error. */
    public SceneLoader(Path file, boolean strict) {
        this.fileName = file.toString();
        this.strict = strict;
        byte[] bytes = readBounded(file);
        parse(bytes);
    }

    /**
     * Loads a scene already in memory (the previewer's uploads, which touch no disk), naming it
     * {@code fileName} in messages exactly as a file of that name would be named.
     */
    public SceneLoader(String fileName, byte[] contents, boolean strict) {
        this.fileName = fileName;
        this.strict = strict;
        if (contents.length > MAX_FILE_BYTES) {
            throw new SceneException(fileName + ": file is " + contents.length + " bytes, expected at most "
                    + MAX_FILE_BYTES + " (64 MiB)");
        }
        parse(contents);
    }

    public Scene getScene() {
        return scene;
    }

    /** One line each, in the same file:line:column form as errors; the render goes on. */
    public List<String> getWarnings() {
        if (warningsLeftOut == 0) {
            return List.copyOf(warnings);
        }
        List<String> all = new ArrayList<>(warnings);
        all.add(fileName + ": warning: " + warningsLeftOut + " more warnings like these, not shown");
        return List.copyOf(all);
    }

    private static Path toPath(String filename) {
        try {
            return Path.of(filename);
        } catch (InvalidPathException e) {
            throw new SceneException(filename + ": not a valid file name");
        }
    }

    private byte[] readBounded(Path file) {
        try {
            if (Files.isDirectory(file)) {
                throw new SceneException(fileName + ": is a directory, expected a scene file");
            }
            return BoundedFile.read(file, MAX_FILE_BYTES);
        } catch (BoundedFile.TooLarge e) {
            throw new SceneException(fileName + (e.size() >= 0 ? ": file is " + e.size() + " bytes, expected at most "
                    + MAX_FILE_BYTES : ": file is larger than " + MAX_FILE_BYTES + " bytes") + " (64 MiB)");
        } catch (NoSuchFileException | AccessDeniedException e) {
            throw new SceneException(fileName + ": " + IoErrors.reason(e));
        } catch (IOException e) {
            throw new SceneException(fileName + ": cannot read: " + IoErrors.reason(e));
        }
    }

    private void parse(byte[] bytes) {
        if (bytes.length == 0) {
            throw new SceneException(fileName + ": file is empty, expected a <scene> element");
        }
        SourcePositions positions = new SourcePositions(decodeLeniently(bytes));
        DocumentReader reader = new DocumentReader(positions);
        Document document;
        try {
            document = SceneDocument.parse(bytes, positions);
        } catch (SceneDocument.Partial stop) {
            // The elements before the stop come first in the file: a problem among them is the
            // file's first problem, and is the one reported.
            reader.read(stop.document());
            throw reasonForStop(stop);
        }
        reader.read(document);
        reader.endOfScene();
    }

    private SceneException reasonForStop(SceneDocument.Partial stop) {
        if (stop.tooManyElementsAt() != null) {
            return new SceneException(fileName + ":" + stop.tooManyElementsAt()
                    + ": too many elements: scene files may have at most " + MAX_ELEMENTS);
        }
        if (stop.getCause() instanceof SAXParseException e) {
            return new SceneException(fileName + ":" + e.getLineNumber() + ":" + e.getColumnNumber()
                    + ": " + SafeXml.describe(e));
        }
        return new SceneException(fileName + ": malformed XML: " + SafeXml.oneLine(stop.getCause().getMessage()));
    }

    /**
     * The file as text, for finding positions in it; bytes that are not UTF-8 become U+FFFD (the
     * parser reports those itself). String's own decoder goes straight to its compact one-byte
     * form for ASCII text, where a CharsetDecoder would first fill a char array twice the file's
     * size: for a 64 MiB file, 128 MiB of heap saved at the loader's peak. A byte-order mark, which
     * Windows editors put first, is left out, as the parser leaves it out of its columns.
     */
    private static String decodeLeniently(byte[] bytes) {
        boolean mark = bytes.length >= 3 && bytes[0] == (byte) 0xEF && bytes[1] == (byte) 0xBB
                && bytes[2] == (byte) 0xBF;
        return mark ? new String(bytes, 3, bytes.length - 3, StandardCharsets.UTF_8)
                : new String(bytes, StandardCharsets.UTF_8);
    }

    /** Walks the document's elements in document order, checking each and adding it to the scene. */
    private final class DocumentReader {

        private final SourcePositions positions;
        private boolean seenPointLight;

        DocumentReader(SourcePositions positions) {
            this.positions = positions;
        }

        void read(Document document) {
            Element root = document.getDocumentElement();
            if (root == null) {
                return;
            }
            SourcePositions.Position at = SceneDocument.positionOf(root);
            if (!root.getTagName().equals(ROOT)) {
                throw error(at, "root element <" + root.getTagName() + ">: expected <scene>");
            }
            checkAttributes(at, root, Set.of());
            // A loop rather than recursion: a hostile file may nest MAX_ELEMENTS elements deep.
            for (Node node = next(root, root); node != null; node = next(node, root)) {
                readElement((Element) node, node.getParentNode() != root);
            }
        }

        /** The no-light warning, which only the whole file can give. */
        void endOfScene() {
            if (!seenPointLight) {
                warn(null, "no <point-light>: the spheres are lit by the ambient light only");
            }
        }

        private void readElement(Element element, boolean nested) {
            SourcePositions.Position at = SceneDocument.positionOf(element);
            String name = element.getTagName();
            if (!ATTRIBUTES.containsKey(name)) {
                throw error(at, "unknown element <" + name + ">: expected sphere, ambient-light or point-light");
            }
            if (nested) {
                warn(at, "<" + name + "> is nested inside another element: read as if directly inside <scene>");
            }
            checkAttributes(at, element, ATTRIBUTES.get(name));
            switch (name) {
                case "sphere" -> scene.addObject(new Sphere(position(at, element),
                        positiveNumber(at, element, "radius", DEFAULTS.get("radius")), colour(at, element)));
                case "ambient-light" -> scene.setAmbientLight(colour(at, element));
                case "point-light" -> {
                    if (seenPointLight) {
                        warn(at, "another <point-light>: Tick 1 models one light, the last one in the file is used");
                    }
                    seenPointLight = true;
                    scene.setPointLight(new PointLight(position(at, element), colour(at, element),
                            nonNegativeNumber(at, element, "intensity", DEFAULTS.get("intensity"))));
                }
                default -> throw new IllegalStateException(name);
            }
        }

        /** The element after {@code node} in document order (depth first), or null after the last. */
        private Node next(Node node, Node root) {
            if (node.getFirstChild() != null) {
                return node.getFirstChild();
            }
            for (Node up = node; up != root; up = up.getParentNode()) {
                if (up.getNextSibling() != null) {
                    return up.getNextSibling();
                }
            }
            return null;
        }

        /** Warns of attributes the element does not have, in the order the file gives them. */
        private void checkAttributes(SourcePositions.Position at, Element element, Set<String> known) {
            for (String attribute : SceneDocument.attributeNames(element)) {
                if (known.contains(attribute)) {
                    continue;
                }
                if (!showsNextWarning()) {
                    // Only counted: finding where it is in the file would cost time for nothing.
                    warningsLeftOut++;
                    continue;
                }
                warn(positions.attribute(at, attribute), element.getTagName() + " attribute \"" + attribute
                        + "\": not part of Tick 1 scenes, ignored"
                        + (known.isEmpty() ? "" : " (expected " + String.join(", ", sorted(known)) + ")")
                        + meant(element, attribute, known));
            }
        }

        /**
         * "; did you mean radius? ..." for a misspelling of an attribute the element leaves out, and
         * the default used instead (none is: under --strict the scene is not rendered).
         */
        private String meant(Element element, String attribute, Set<String> known) {
            return Misspelling.meant(attribute, known).filter(name -> !element.hasAttribute(name))
                    .map(name -> "; did you mean " + name + "?" + (DEFAULTS.containsKey(name) && !strict
                            ? " " + name + " is not given, so the default " + plain(DEFAULTS.get(name)) + " is used"
                            : "")).orElse("");
        }

        private static String plain(double value) {
            return value == Math.rint(value) ? Long.toString((long) value) : Double.toString(value);
        }

        private Vector3 position(SourcePositions.Position at, Element element) {
            return new Vector3(number(at, element, "x", DEFAULTS.get("x")), number(at, element, "y", DEFAULTS.get("y")),
                    number(at, element, "z", DEFAULTS.get("z")));
        }

        private double positiveNumber(SourcePositions.Position at, Element element, String attribute,
                double fallback) {
            double value = number(at, element, attribute, fallback);
            if (!(value > 0)) {
                throw attributeError(at, element, attribute, "must be a number greater than 0");
            }
            return value;
        }

        private double nonNegativeNumber(SourcePositions.Position at, Element element, String attribute,
                double fallback) {
            double value = number(at, element, attribute, fallback);
            if (value < 0) {
                throw attributeError(at, element, attribute, "must be a number of at least 0");
            }
            return value;
        }

        private double number(SourcePositions.Position at, Element element, String attribute, double fallback) {
            if (!element.hasAttribute(attribute)) {
                return fallback;
            }
            String trimmed = element.getAttribute(attribute).strip();
            if (NON_FINITE.matcher(trimmed).matches()) {
                throw attributeError(at, element, attribute, "must be a finite decimal number");
            }
            if (!DECIMAL.matcher(trimmed).matches()) {
                throw attributeError(at, element, attribute, "must be a decimal number such as 1.5 or -2e3");
            }
            double value = Double.parseDouble(trimmed);
            if (!(Math.abs(value) <= MAX_MAGNITUDE)) {
                throw attributeError(at, element, attribute,
                        "must be a number between -1e16 and 1e16 (the range the renderer is tested for)");
            }
            return value;
        }

        private Vector3 colour(SourcePositions.Position at, Element element) {
            if (!element.hasAttribute("colour")) {
                String misspelt = SceneDocument.attributeNames(element).stream()
                        .filter(name -> Misspelling.meant(name, Set.of("colour")).isPresent()).findFirst()
                        .map(name -> " (the tick spells it colour, not " + name + ")").orElse("");
                throw error(at, element.getTagName() + " has no colour: expected colour=\"#RRGGBB\"" + misspelt);
            }
            String text = element.getAttribute("colour");
            if (!COLOUR.matcher(text).matches()) {
                throw attributeError(at, element, "colour",
                        "must be # followed by six hexadecimal digits, as in #FF8800");
            }
            // Each channel is value / 255.0 (the starter code's conversion).
            int rgb = Integer.parseInt(text.substring(1), 16);
            return new Vector3((rgb >> 16 & 0xFF) / 255.0, (rgb >> 8 & 0xFF) / 255.0, (rgb & 0xFF) / 255.0);
        }

        private SceneException attributeError(SourcePositions.Position at, Element element, String attribute,
                String expected) {
            return error(positions.attribute(at, attribute), element.getTagName() + " " + attribute + " \""
                    + printable(element.getAttribute(attribute)) + "\": " + expected);
        }

        private SceneException error(SourcePositions.Position at, String message) {
            return new SceneException(fileName + (at == null ? "" : ":" + at) + ": " + message);
        }

        /** Whether the next warning is printed (or, under --strict, is the error), not only counted. */
        private boolean showsNextWarning() {
            return strict || warnings.size() < MAX_WARNINGS;
        }

        private void warn(SourcePositions.Position at, String message) {
            if (strict) {
                throw error(at, message + " (an error under --strict)");
            }
            if (warnings.size() < MAX_WARNINGS) {
                warnings.add(fileName + (at == null ? "" : ":" + at) + ": warning: " + message);
            } else {
                warningsLeftOut++;
            }
        }
    }

    private static List<String> sorted(Set<String> names) {
        List<String> list = new ArrayList<>(names);
        list.sort(null);
        return list;
    }

    /** Keeps a quoted value on one short line, whatever the file held. */
    private static String printable(String value) {
        String flat = value.replaceAll("\\p{Cntrl}", "?");
        return flat.length() <= 40 ? flat : flat.substring(0, 37) + "...";
    }

}
