"use strict";
// A machine's figure, from hfsm-graph's SVG text, rebuilt element by element from a parsed copy:
// only the elements and attributes Graphviz draws with are kept (no script, no event handler, no
// link, no foreign object, no style, no url()); every text stays text. So a name or a doc in a
// machine file cannot run code in the page, whatever the SVG holds.

const SAFE_TAGS = new Set(["svg", "g", "title", "desc", "a", "path", "polygon", "polyline", "ellipse",
                           "circle", "rect", "line", "text", "tspan"]);
const SAFE_ATTRS = new Set(["id", "class", "width", "height", "viewBox", "transform", "d", "points", "cx",
                            "cy", "rx", "ry", "r", "x", "y", "x1", "x2", "y1", "y2", "dx", "dy", "fill",
                            "stroke", "stroke-width", "stroke-dasharray", "stroke-opacity", "fill-opacity",
                            "font-family", "font-size", "font-weight", "font-style", "text-anchor", "opacity",
                            "preserveAspectRatio", "xml:space", "xlink:title"]);
const MAX_TEXT = 2000;  // characters of one text shown; the rest is cut (a 10 MB name must not stall layout)

function clip(text) {
  const s = String(text);
  return s.length > MAX_TEXT ? `${s.slice(0, MAX_TEXT)}… (${s.length} characters)` : s;
}

// The SVG element for `text`, or null when it is not an SVG document.
function safeSvg(text) {
  const doc = new DOMParser().parseFromString(text, "image/svg+xml");
  const root = doc.documentElement;
  if (!root || root.namespaceURI !== SVGNS || root.localName !== "svg") return null;
  return cleanSvg(root);
}

function cleanSvg(node) {
  const out = document.createElementNS(SVGNS, node.localName);
  for (const attr of node.attributes) {
    if (!SAFE_ATTRS.has(attr.name) || /url\s*\(|javascript:/i.test(attr.value)) continue;
    const value = attr.name === "xlink:title" ? clip(attr.value) : attr.value;  // geometry is never cut
    if (attr.namespaceURI) out.setAttributeNS(attr.namespaceURI, attr.name, value);
    else out.setAttribute(attr.name, value);
  }
  for (const child of node.childNodes) {
    if (child.nodeType === Node.TEXT_NODE) out.append(document.createTextNode(clip(child.data)));
    else if (child.nodeType === Node.ELEMENT_NODE && child.namespaceURI === SVGNS && SAFE_TAGS.has(child.localName)) {
      out.append(cleanSvg(child));
    }
  }
  return out;
}

if (typeof module !== "undefined") module.exports = { clip };
