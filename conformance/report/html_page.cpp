// html_page.cpp — see html_page.h.
#include "html_page.h"

#include <pugixml.hpp>

#include "display_text.h"

#include <sstream>

namespace vgc {
namespace {

// Written as is into the <style> element (no "</" in it).
const char* const kStyle = R"css(
body { font-family: sans-serif; margin: 1.5em auto; max-width: 1100px; color: #1b1b1b; background: #ffffff; }
h1 { font-size: 1.5em; margin-bottom: 0.3em; }
.verdict { display: inline-block; padding: 0.25em 0.7em; border-radius: 4px; color: #ffffff; font-weight: bold; }
.verdict.conformant { background: #2e7d32; }
.verdict.not-conformant { background: #c62828; }
.verdict.incomplete { background: #8d6e00; }
.counts span.st { margin-right: 0.5em; }
.st { display: inline-block; padding: 0.05em 0.45em; border-radius: 3px; border: 1px solid #bbbbbb; white-space: nowrap; }
.st-pass { background: #e8f5e9; color: #1b5e20; border-color: #81c784; }
.st-fail { background: #ffebee; color: #b71c1c; border-color: #e57373; }
.st-crash { background: #f3e5f5; color: #6a1b9a; border-color: #ba68c8; }
.st-timeout { background: #fff3e0; color: #bf360c; border-color: #ffb74d; }
.st-unchecked { background: #fff8e1; color: #7a5c00; border-color: #ffd54f; }
.st-not-applicable { background: #eceff1; color: #37474f; border-color: #b0bec5; }
.st-not-claimed { background: #f5f5f5; color: #455a64; border-color: #cfd8dc; }
.st-skipped { background: #fafafa; color: #757575; border-color: #e0e0e0; }
.st-profile-difference { background: #e1f5fe; color: #01579b; border-color: #4fc3f7; }
.st-should { background: #fffde7; color: #795548; border-color: #fff176; }
.st-known { background: #fbe9e7; color: #6d4c41; border-color: #bcaaa4; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em 0; font-size: 0.92em; }
th, td { border: 1px solid #dddddd; padding: 0.2em 0.5em; text-align: left; vertical-align: top; }
th { background: #f4f4f4; }
pre { background: #f6f8fa; border: 1px solid #e1e4e8; padding: 0.6em; overflow-x: auto; font-size: 0.88em; }
code { background: #f6f8fa; padding: 0 0.2em; }
blockquote { border-left: 4px solid #9e9e9e; margin: 0.5em 0; padding: 0.2em 0.8em; color: #333333; background: #fafafa; }
section.finding { border: 1px solid #dddddd; border-radius: 6px; padding: 0.2em 1em 0.8em 1em; margin: 1em 0; }
figure { margin: 0.5em 0; }
figcaption { font-size: 0.9em; color: #333333; max-width: 640px; }
svg.mesh, svg.plot { border: 1px solid #cccccc; }
ul.legend { font-size: 0.85em; padding-left: 1.2em; margin: 0.3em 0; }
.sw { font-weight: bold; }
.note { color: #555555; font-size: 0.9em; }
)css";

}  // namespace

void escape_unprintable_tree(pugi::xml_node root) {
  for (pugi::xml_attribute a : root.attributes()) a.set_value(escape_unprintable(a.value()).c_str());
  if (root.type() == pugi::node_pcdata || root.type() == pugi::node_cdata || root.type() == pugi::node_comment)
    root.set_value(escape_unprintable(root.value()).c_str());
  for (pugi::xml_node child : root.children()) escape_unprintable_tree(child);
}

std::string html_page(const pugi::xml_node& title, const pugi::xml_node& body) {
  escape_unprintable_tree(title);
  escape_unprintable_tree(body);
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'\">\n";
  const unsigned flags = pugi::format_raw | pugi::format_no_declaration | pugi::format_no_empty_element_tags;
  title.print(out, "", flags);
  out << "\n<style>" << kStyle << "</style>\n</head>\n";
  body.print(out, "", flags);
  out << "\n</html>\n";
  return out.str();
}

}  // namespace vgc
