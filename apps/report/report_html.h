// The building blocks of `raster report`'s page (report.h): escaping, number cells, tables,
// figures and collapsible panels, and the page around them with its inline style sheet.
//
// The page is self-contained: no script, no external style sheet, no font, no network; its
// images are files beside index.html, named by relative paths. Every text that reaches the
// HTML goes through escape() (scene, target, program and file names, JSON keys and values),
// so a name holding '<' or '"' shows as itself and can never open a tag or end an attribute.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace report {

// Text for an HTML element or a quoted attribute value: & < > " ' as character references.
std::string escape(const std::string& text);

// A JSON value as a short text for a cell: numbers with 6 significant digits, arrays as
// "[a, b, c]" (recursively), strings as they are, null as "-", objects as compact JSON.
std::string jsonText(const nlohmann::json& value);

// A table: a header row and body rows of cells that are already HTML (escape text first).
// `id` (optional) names the table for the page's readers and the tests.
struct Table {
  std::string id, caption;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::string html() const;
};

// A cell holding a number: shows `shown`, and carries the value the page was made from in
// data-value, so a reader (and the Chromium test) can check the two against the JSON.
std::string numberCell(const std::string& shown, const nlohmann::json& value);

// An image file beside the page with a caption under it. `file` is relative to index.html;
// `link` (optional) is a data file the caption links to (an EXR dump).
std::string figure(const std::string& file, const std::string& caption, const std::string& link = "",
                   const std::string& linkText = "");

// A collapsible panel (<details>); `summary` and `body` are HTML.
std::string details(const std::string& summary, const std::string& body, bool open = false);

// A note in a box, for what the report could not show (a child that failed, no chart found).
std::string note(const std::string& text);

// A name that becomes part of a file name and an HTML id: letters, digits, - _ . kept,
// anything else '_' ("_" for an empty name).
std::string fileSafe(const std::string& name);

// The whole page: title, inline style, a table of contents of the sections, the body.
struct Section {
  std::string id, title, html;
};
std::string page(const std::string& title, const std::string& intro, const std::vector<Section>& sections);

}  // namespace report
