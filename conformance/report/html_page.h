// html_page.h — the frame of vgc's HTML pages (report.html of certify and
// of fuzz campaigns): doctype, charset, a Content-Security-Policy that
// forbids loading anything (so the page is self-contained, and any attempt
// to load something is a console error a test sees), one inline style.
//
// Spec: none (reporting).
//
// Rationale: the pages are built as pugixml trees (escaping done by the
// library) and printed raw, with no empty-element tags, so an HTML parser
// reads every element as written; the few parts an XML writer cannot give
// (doctype, the void <meta> elements) are written here, fixed.
#pragma once

#include <string>

namespace pugi {
class xml_node;
}

namespace vgc {

// "<!DOCTYPE html><html><head>...<title/>...<style/></head><body/></html>".
std::string html_page(const pugi::xml_node& title, const pugi::xml_node& body);

// Escapes (display_text.h) every attribute value and text under `root`, in
// place: pugixml writes a control byte as a character reference, which
// XML 1.0 does not allow and which a browser shows raw. html_page and
// junit.xml call it before printing.
void escape_unprintable_tree(pugi::xml_node root);

}  // namespace vgc
