package org.usarsim.wss.world;

import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import javax.xml.XMLConstants;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParser;
import javax.xml.parsers.SAXParserFactory;
import org.xml.sax.Attributes;
import org.xml.sax.InputSource;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;
import org.xml.sax.helpers.DefaultHandler;

/**
 * The elements of an SDF document that its walls are made of, read with the JDK's SAX parser
 * hardened: secure processing on, any DOCTYPE refused (so no entity, internal or external, is
 * ever declared or expanded, and no DTD is loaded), no external access, no XInclude. Only the
 * elements on the way to a collision's geometry are kept (models, links, collisions, poses,
 * geometries and includes); a subtree of anything else (visuals, plugins, physics, ...) is
 * skipped as it is read.
 */
final class SdfElements {

    /** An element kept: its tag, the attributes SDF walls need, its text (poses, sizes, URIs) and children. */
    static final class Element {
        final String tag;
        final Map<String, String> attributes = new HashMap<>(2);
        final List<Element> children = new ArrayList<>();
        final StringBuilder text = new StringBuilder();

        Element(String tag) {
            this.tag = tag;
        }

        String attribute(String name) {
            return attributes.getOrDefault(name, "");
        }

        /** The first child of this tag; null when none. */
        Element child(String childTag) {
            for (Element child : children) {
                if (child.tag.equals(childTag)) {
                    return child;
                }
            }
            return null;
        }

        String text() {
            return text.toString().strip();
        }
    }

    /** The geometries SDF knows besides box: skipped, counted by kind. */
    static final Set<String> OTHER_GEOMETRIES = Set.of("mesh", "cylinder", "sphere", "plane", "capsule", "ellipsoid",
            "polyline", "heightmap", "image", "empty");

    private static final Set<String> KEPT = Set.of("sdf", "world", "model", "link", "collision", "pose",
            "geometry", "box", "size", "include", "uri", "name");
    private static final Set<String> WITH_TEXT = Set.of("pose", "size", "uri", "name");
    private static final Set<String> ATTRIBUTES = Set.of("name", "relative_to", "frame", "degrees", "rotation_format");
    /** A text longer than this (a pose, a size, a URI) is cut: no real one is near it. */
    private static final int MAX_TEXT = 4096;

    private SdfElements() {
    }

    /** The document's root element, its kept subtree. */
    static Element read(InputStream in, String source) throws WorldFileException {
        Handler handler = new Handler();
        try {
            parser().parse(new InputSource(in), handler);
        } catch (SAXParseException e) {
            String message = String.valueOf(e.getMessage());
            if (message.contains("DOCTYPE") || message.contains("doctype")) {
                throw new WorldFileException(source + ": a DOCTYPE is refused (SDF needs none; entities and DTDs are never read): line "
                        + e.getLineNumber());
            }
            throw new WorldFileException(source + ":" + e.getLineNumber() + ": not well-formed XML: " + message);
        } catch (SAXException e) {
            throw new WorldFileException(source + ": not an SDF document: " + e.getMessage());
        } catch (IOException e) {
            throw new WorldFileException(source + ": cannot read it: " + e.getMessage());
        }
        if (handler.root == null) {
            throw new WorldFileException(source + ": no root element");
        }
        return handler.root;
    }

    private static SAXParser parser() throws WorldFileException {
        try {
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
            // No DOCTYPE means no entity but the five predefined; these limits hold even so.
            parser.setProperty("jdk.xml.entityExpansionLimit", "100");
            parser.setProperty("jdk.xml.maxGeneralEntitySizeLimit", "4096");
            parser.setProperty("jdk.xml.totalEntitySizeLimit", "65536");
            parser.setProperty("jdk.xml.elementAttributeLimit", "100");
            return parser;
        } catch (ParserConfigurationException | SAXException e) {
            throw new IllegalStateException("the JDK's XML parser refuses a hardening setting", e);
        }
    }

    /** Builds the kept tree; counts the depth of a skipped subtree. */
    private static final class Handler extends DefaultHandler {

        private final Deque<Element> open = new ArrayDeque<>();
        private Element root;
        private int skipping;

        @Override
        public void startElement(String uri, String localName, String qName, Attributes attributes) {
            if (skipping > 0 || root != null && !(KEPT.contains(qName) || OTHER_GEOMETRIES.contains(qName) && inGeometry())) {
                skipping++;
                return;
            }
            Element element = new Element(qName);
            for (String name : ATTRIBUTES) {
                String value = attributes.getValue(name);
                if (value != null) {
                    element.attributes.put(name, value);
                }
            }
            if (open.isEmpty()) {
                root = element;
            } else {
                open.peek().children.add(element);
            }
            open.push(element);
        }

        private boolean inGeometry() {
            return !open.isEmpty() && open.peek().tag.equals("geometry");
        }

        @Override
        public void endElement(String uri, String localName, String qName) {
            if (skipping > 0) {
                skipping--;
            } else {
                open.pop();
            }
        }

        @Override
        public void characters(char[] ch, int start, int length) {
            Element element = open.peek();
            if (skipping == 0 && element != null && WITH_TEXT.contains(element.tag)
                    && element.text.length() + length <= MAX_TEXT) {
                element.text.append(ch, start, length);
            }
        }
    }
}
