package gfx.tick1.scene;

import java.io.ByteArrayInputStream;
import java.io.IOException;
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
 * the element as DOM user data ({@link Node#setUserData}). Only elements and attributes are kept.
 * Text and comments carry nothing in a Tick 1 scene, and leaving them out keeps a large file's
 * tree small.
 *
 * <p>Building stops at {@link SceneLoader#MAX_ELEMENTS} elements, so that a hostile file cannot
 * fill memory with a tree. When the parser stops early, on malformed XML or at that limit, the
 * elements read so far are kept ({@link Partial#document()}): the loader checks them first, so
 * that a file's first problem is the one reported, as when each element was checked as it came.
 */
final class SceneDocument {

    private static final String POSITION = "tick1.position";

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

        /** Where the element over the limit starts, or null when the XML itself was malformed. */
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
        return (SourcePositions.Position) element.getUserData(POSITION);
    }

    private static Document newDocument() {
        try {
            Document document = DocumentBuilderFactory.newInstance().newDocumentBuilder().newDocument();
            // Every name comes from the parser, which has already checked it is a legal XML name;
            // checking it again for each of up to a million elements costs time and finds nothing.
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

    /** Turns the parser's events into elements, each appended to the element it is inside. */
    private static final class Builder extends DefaultHandler {

        private final Document document;
        private final SourcePositions positions;
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
            for (int i = 0; i < attributes.getLength(); i++) {
                element.setAttribute(attributes.getQName(i), attributes.getValue(i));
            }
            element.setUserData(POSITION, at, null);
            current.appendChild(element);
            current = element;
        }

        @Override
        public void endElement(String uri, String localName, String name) {
            current = current.getParentNode();
        }
    }
}
