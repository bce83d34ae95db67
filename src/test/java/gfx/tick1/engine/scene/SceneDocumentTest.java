package gfx.tick1.engine.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * The loader's model of a scene file is a DOM {@link Document} whose elements carry the line and
 * column of their start tags, so that a loader walking the tree can still point at the file.
 */
class SceneDocumentTest {

    private static final String SCENE = """
            <?xml version="1.0"?>
            <scene>
              <!-- a comment, then elements on lines of their own and two on one line -->
              <ambient-light colour="#555555"/>
                <point-light x="1" y="3" z="2"
                             colour="#B3DDFF" intensity="120"/>
              <sphere z="3.5" colour="#0071BC"/><sphere z="5" radius="0.9" colour="#FF1D25">\
            <sphere colour="#000000"/></sphere>
            </scene>
            """;

    private static Document parse(String xml) throws SceneDocument.Partial {
        return SceneDocument.parse(xml.getBytes(StandardCharsets.UTF_8), new SourcePositions(xml));
    }

    private static List<Element> elementsInDocumentOrder(Document document) {
        NodeList all = document.getElementsByTagName("*");
        List<Element> elements = new ArrayList<>();
        for (int i = 0; i < all.getLength(); i++) {
            elements.add((Element) all.item(i));
        }
        return elements;
    }

    @Test
    void theFileIsReadIntoADomDocumentOfItsElementsAndAttributes() throws Exception {
        Document document = parse(SCENE);

        assertThat(document.getDocumentElement().getTagName()).isEqualTo("scene");
        assertThat(elementsInDocumentOrder(document)).extracting(Element::getTagName)
                .containsExactly("scene", "ambient-light", "point-light", "sphere", "sphere", "sphere");
        Element light = (Element) document.getElementsByTagName("point-light").item(0);
        assertThat(light.getAttribute("intensity")).isEqualTo("120");
        assertThat(light.getAttributes().getLength()).isEqualTo(5);
    }

    @Test
    void everyElementCarriesTheLineAndColumnOfItsStartTag() throws Exception {
        List<String> lines = SCENE.lines().toList();
        for (Element element : elementsInDocumentOrder(parse(SCENE))) {
            SourcePositions.Position at = SceneDocument.positionOf(element);

            assertThat(at).as("position of <%s>", element.getTagName()).isNotNull();
            assertThat(lines.get(at.line() - 1).substring(at.column() - 1))
                    .as("the text at %s, where <%s> is recorded to start", at, element.getTagName())
                    .startsWith("<" + element.getTagName());
        }
    }

    @Test
    void textAndCommentsAreLeftOutOfTheTree() throws Exception {
        Document document = parse(SCENE);

        for (Element element : elementsInDocumentOrder(document)) {
            for (int i = 0; i < element.getChildNodes().getLength(); i++) {
                assertThat(element.getChildNodes().item(i)).as("a child of <%s>", element.getTagName())
                        .isInstanceOf(Element.class);
            }
        }
    }

    @Test
    void theParseStopsAtTheFirstElementTheFormatDoesNotHave() {
        // Nothing after <plane> is read: not the next sphere, not the malformed end.
        String xml = "<scene>\n<sphere colour='#FF0000'/>\n<plane/>\n<sphere colour='#00FF00'/>\n<broken\n";

        assertThatThrownBy(() -> parse(xml)).isInstanceOfSatisfying(SceneDocument.Partial.class, stop ->
                assertThat(elementsInDocumentOrder(stop.document())).extracting(Element::getTagName)
                        .containsExactly("scene", "sphere", "plane"));
    }

    @Test
    void attributesAreNamedInTheFilesOrderAndOnlyTheFormatsAreKeptWithTheirValues() throws Exception {
        Element sphere = (Element) parse("<scene><sphere zeta='1' x='2' alpha='3' colour='#FF0000'/></scene>")
                .getElementsByTagName("sphere").item(0);

        assertThat(SceneDocument.attributeNames(sphere)).containsExactly("zeta", "x", "alpha", "colour");
        assertThat(sphere.getAttribute("x")).isEqualTo("2");
        assertThat(sphere.hasAttribute("zeta")).as("an attribute spheres do not have, kept in the tree").isFalse();
        assertThat(sphere.getAttributes().getLength()).isEqualTo(2);
    }

    @Test
    void malformedXmlStopsTheParseButKeepsTheElementsBeforeIt() {
        String xml = "<scene>\n<sphere colour='#FF0000'/>\n<ambient-light colour='#000000'>\n</scene>\n";

        assertThatThrownBy(() -> parse(xml)).isInstanceOfSatisfying(SceneDocument.Partial.class, stop -> {
            assertThat(stop.tooManyElementsAt()).isNull();
            assertThat(elementsInDocumentOrder(stop.document())).extracting(Element::getTagName)
                    .containsExactly("scene", "sphere", "ambient-light");
        });
    }
}
