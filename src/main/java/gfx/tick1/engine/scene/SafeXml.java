package gfx.tick1.engine.scene;

import java.io.StringReader;
import java.util.Locale;
import javax.xml.XMLConstants;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParser;
import javax.xml.parsers.SAXParserFactory;
import org.xml.sax.InputSource;
import org.xml.sax.SAXException;
import org.xml.sax.SAXNotRecognizedException;
import org.xml.sax.SAXNotSupportedException;
import org.xml.sax.SAXParseException;

/**
 * The JDK's SAX parser, configured for files from strangers, and the wording of its complaints.
 *
 * <p>Scene files come from students, the internet and other people's submissions, so the parser
 * follows OWASP's XML External Entity Prevention advice for the JDK. The one setting that
 * matters is the first: with DOCTYPE refused there is nowhere to declare an entity, so external
 * entities (XXE: reading local files or URLs into the document), parameter entities and
 * entity-expansion bombs ("billion laughs") are all stopped at the first {@code <!DOCTYPE}, before
 * anything is read or expanded. Every other setting is a second line of defence in case a later
 * change allows DOCTYPE again: no external general or parameter entities, no external DTD, no
 * XInclude, an empty list of protocols for external access, an entity resolver that refuses,
 * and secure processing, which caps entity expansion, attribute count and name length.
 */
final class SafeXml {

    private SafeXml() {
    }

    static SAXParser newParser() throws ParserConfigurationException, SAXException {
        SAXParserFactory factory = SAXParserFactory.newInstance();
        factory.setNamespaceAware(false);
        factory.setValidating(false);
        factory.setXIncludeAware(false);
        factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
        factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        factory.setFeature("http://xml.org/sax/features/external-general-entities", false);
        factory.setFeature("http://xml.org/sax/features/external-parameter-entities", false);
        factory.setFeature("http://apache.org/xml/features/nonvalidating/load-external-dtd", false);
        SAXParser parser = factory.newSAXParser();
        parser.setProperty(XMLConstants.ACCESS_EXTERNAL_DTD, "");
        parser.setProperty(XMLConstants.ACCESS_EXTERNAL_SCHEMA, "");
        // The parser's messages are read by people and compared by tests: the same words
        // whatever the machine's language.
        setIfSupported(parser, "http://apache.org/xml/properties/locale", Locale.ROOT);
        parser.getXMLReader().setEntityResolver((publicId, systemId) -> new InputSource(new StringReader("")));
        return parser;
    }

    private static void setIfSupported(SAXParser parser, String property, Object value) {
        try {
            parser.setProperty(property, value);
        } catch (SAXNotRecognizedException | SAXNotSupportedException e) {
            // Another JAXP implementation: its messages may be localised, nothing worse.
        }
    }

    /**
     * The parser's complaint, reworded where its own words are obscure. Its message never holds
     * document content beyond names (no entity is ever expanded), but it is kept to one line.
     */
    static String describe(SAXParseException e) {
        // "JAXP00010002: ..." names a secure-processing limit; the code means nothing to a reader.
        String raw = oneLine(e.getMessage());
        String message = raw.replaceFirst("^JAXP\\d+: ", "");
        if (message.contains("disallow-doctype-decl") || message.contains("DOCTYPE")) {
            return "DOCTYPE declaration: not allowed in scene files (no DTDs or entities), expected <scene>";
        }
        if (message.startsWith("XML document structures must start and end within the same entity")) {
            return "malformed XML: the file ends in the middle of the scene (a tag, comment or element is "
                    + "left open), expected it to end with </scene>";
        }
        if (message.startsWith("Premature end of file")) {
            return "malformed XML: the file ends before its first element, expected <scene>";
        }
        if (message.startsWith("Content is not allowed in prolog")) {
            return "malformed XML: text before the first element, expected the file to start with <scene> "
                    + "(or <?xml ...?>)";
        }
        if (message.startsWith("The markup in the document following the root element")) {
            return "malformed XML: more after </scene>, expected the file to end with the scene";
        }
        if (message.startsWith("The processing instruction target matching \"[xX][mM][lL]\" is not allowed")) {
            return "malformed XML: <?xml ...?> declaration after the start of the file, expected it first "
                    + "(or not at all)";
        }
        if (raw.startsWith("JAXP00010005")) { // secure processing's limit on name length
            return "malformed XML: an element or attribute name longer than 1000 characters (the parser's "
                    + "limit), expected names such as sphere or radius";
        }
        if (message.startsWith("Invalid byte ") && message.contains("UTF-8")) {
            return "malformed XML: bytes that are not UTF-8 (" + message + "), expected a UTF-8 text file";
        }
        return "malformed XML: " + message;
    }

    static String oneLine(String message) {
        return message == null ? "unknown error" : message.replaceAll("\\s+", " ").trim();
    }
}
