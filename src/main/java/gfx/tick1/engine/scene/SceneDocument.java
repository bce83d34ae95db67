package gfx.tick1.engine.scene;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.xml.sax.Attributes;
import org.xml.sax.InputSource;
import org.xml.sax.Locator;
import org.xml.sax.SAXException;
import org.xml.sax.helpers.DefaultHandler;

/**
 * A scene file read into a DOM {@link Document} whose elements remember where they start in the
 * file, so that the loader can walk a tree and still name the line and column of what is wrong.
 *
 * <p>A DOM built by the JDK's DocumentBuilder forgets positions. This one is built by hand from
 * the events of the locked-down SAX parser ({@link SafeXml}): each start tag becomes an element
 * with its attributes, and the tag's position, found through the SAX {@link Locator}, is stored on
 * the element as DOM user data ({@link Node#setUserData}), with the names of its attributes in the
 * file's order (a DOM keeps them in an order of its own, and a message about several of them
 * should follow the file). Only what a scene can use is kept: elements, and the attributes each
 * element of the format has. Text, comments and the values of attributes the format does not have
 * carry nothing in a Tick 1 scene (such an attribute is only named in a warning), and leaving them
 * out keeps the tree of even a hostile 64 MiB file within the loader's memory budget.
 *
 * <p>Building stops early, so that a hostile file is never read whole into memory for nothing:
 * at {@link SceneLoader#MAX_ELEMENTS} elements, and at the first element whose name the scene
 * format does not have (which the loader will refuse anyway). The elements read so far are kept
 * ({@link Partial#document()}), the one that stopped the parse among them: the loader checks them
 * first, so that a file's first problem is the one reported, as when each element was checked as
 * it came.
 */
final class SceneDocument {

    private static final String ORIGIN = "tick1.origin";

    /** Where an element's start tag begins in the file, and its attributes' names in the file's order. */
    record Origin(SourcePositions.Position at, List<String> attributeNames) {
    }

    /** Parsing stopped early; {@link #document()} holds every element before the stop. */
    static final class Partial extends Exception {
        private static final long serialVersionUID = 1L;

        private final transient Document document;
        private final transient SourcePositions.Position at;

        Partial(Exception cause, Document document, SourcePositions.Position at) {
            super(cause);
            this.document = document;
            this.at = at;
        }

        /** The elements read before parsing stopped. */
        Document document() {
            return document;
        }

        /** Where the element over the limit starts, or null when parsing stopped for another reason. */
        SourcePositions.Position tooManyElementsAt() {
            return at;
        }
    }

    private SceneDocument() {
    }

    /** Reads {@code bytes} (located in {@code positions}) into a document. */
    static Document parse(byte[] bytes, SourcePositions positions) throws Partial {
        Document document = newDocument();
        Builder builder = new Builder(document, positions);
        try {
            SafeXml.newParser().parse(new InputSource(new ByteArrayInputStream(bytes)), builder);
        } catch (TooManyElements e) {
            throw new Partial(e, document, e.at);
        } catch (SAXException | IOException | ParserConfigurationException e) {
            throw new Partial(e, document, null);
        }
        return document;
    }

    /** Where the start tag of {@code element} begins in the file. */
    static SourcePositions.Position positionOf(Element element) {
        return origin(element).at();
    }

    /**
     * The names of all the attributes the file gives {@code element}, in the file's order, including
     * those the format does not have (which are not in the tree).
     */
    static List<String> attributeNames(Element element) {
        return origin(element).attributeNames();
    }

    private static Origin origin(Element element) {
        return (Origin) element.getUserData(ORIGIN);
    }

    private static Document newDocument() {
        try {
            Document document = DocumentBuilderFactory.newInstance().newDocumentBuilder().newDocument();
            // Every name comes from the parser, which has already checked it is a legal XML name;
            // checking it again for each of up to MAX_ELEMENTS elements costs time and finds nothing.
            document.setStrictErrorChecking(false);
            return document;
        } catch (ParserConfigurationException e) {
            throw new IllegalStateException("the JDK has no DOM implementation", e);
        }
    }

    /** Raised from inside the parser at the first element over the limit. */
    private static final class TooManyElements extends SAXException {
        private static final long serialVersionUID = 1L;

        private final transient SourcePositions.Position at;

        TooManyElements(SourcePositions.Position at) {
            super("too many elements");
            this.at = at;
        }
    }

    /** Raised from inside the parser once an element the format does not have is in the tree. */
    private static final class UnknownElement extends SAXException {
        private static final long serialVersionUID = 1L;

        UnknownElement(String name) {
            super("unknown element <" + name + ">");
        }
    }

    /** Turns the parser's events into elements, each appended to the element it is inside. */
    private static final class Builder extends DefaultHandler {

        /** How many different orders of attribute names are shared between elements. */
        private static final int SHARED_ORDERS = 64;

        private final Document document;
        private final SourcePositions positions;
        /** One list for each order of attribute names met: a scene's spheres usually share one. */
        private final Map<List<String>, List<String>> orders = new HashMap<>();
        private Locator locator;
        private Node current;
        private int elements;

        Builder(Document document, SourcePositions positions) {
            this.document = document;
            this.positions = positions;
            this.current = document;
        }

        @Override
        public void setDocumentLocator(Locator locator) {
            this.locator = locator;
        }

        @Override
        public void startElement(String uri, String localName, String name, Attributes attributes)
                throws SAXException {
            SourcePositions.Position at = positions.tagStart(locator.getLineNumber(), locator.getColumnNumber());
            if (++elements > SceneLoader.MAX_ELEMENTS) {
                throw new TooManyElements(at);
            }
            Element element = document.createElement(name);
            Set<String> used = SceneLoader.ATTRIBUTES.getOrDefault(name, Set.of());
            List<String> names = new ArrayList<>(attributes.getLength());
            for (int i = 0; i < attributes.getLength(); i++) {
                String attribute = attributes.getQName(i);
                if (used.contains(attribute)) {
                    element.setAttribute(attribute, attributes.getValue(i));
                }
                names.add(attribute);
            }
            element.setUserData(ORIGIN, new Origin(at, shared(names)), null);
            current.appendChild(element);
            current = element;
            if (!name.equals(SceneLoader.ROOT) && !SceneLoader.ATTRIBUTES.containsKey(name)) {
                throw new UnknownElement(name);
            }
        }

        @Override
        public void endElement(String uri, String localName, String name) {
            current = current.getParentNode();
        }

        private List<String> shared(List<String> names) {
            List<String> known = orders.get(names);
            if (known != null) {
                return known;
            }
            List<String> copy = List.copyOf(names);
            if (orders.size() < SHARED_ORDERS) {
                orders.put(copy, copy);
            }
            return copy;
        }
    }
}
