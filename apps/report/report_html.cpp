// HTML building blocks of the report page (report_html.h).
#include "apps/report/report_html.h"

#include <cctype>
#include <cstdio>

namespace report {

std::string escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string jsonText(const nlohmann::json& value) {
  if (value.is_null()) return "-";
  if (value.is_string()) return value.get<std::string>();
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
  if (value.is_number_integer() || value.is_number_unsigned()) return value.dump();
  if (value.is_number_float()) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value.get<double>());
    return text;
  }
  if (value.is_array()) {
    std::string text = "[";
    for (size_t i = 0; i < value.size(); ++i) text += (i ? ", " : "") + jsonText(value[i]);
    return text + "]";
  }
  return value.dump();
}

std::string Table::html() const {
  std::string out = "<table" + (id.empty() ? std::string() : " id=\"" + escape(id) + "\"") + ">";
  if (!caption.empty()) out += "<caption>" + escape(caption) + "</caption>";
  out += "<thead><tr>";
  for (const std::string& h : header) out += "<th>" + escape(h) + "</th>";
  out += "</tr></thead><tbody>";
  for (const auto& row : rows) {
    out += "<tr>";
    for (const std::string& cell : row) out += cell.rfind("<td", 0) == 0 ? cell : "<td>" + cell + "</td>";
    out += "</tr>";
  }
  return out + "</tbody></table>\n";
}

std::string numberCell(const std::string& shown, const nlohmann::json& value) {
  // dump() of a double keeps every bit (nlohmann-json writes the shortest round-trip form).
  return "<td class=\"num\" data-value=\"" + escape(value.dump()) + "\">" + escape(shown) + "</td>";
}

std::string figure(const std::string& file, const std::string& caption, const std::string& link,
                   const std::string& linkText) {
  std::string out = "<figure><a href=\"" + escape(file) + "\"><img src=\"" + escape(file) + "\" alt=\"" +
                    escape(caption) + "\"></a><figcaption>" + escape(caption);
  if (!link.empty()) out += " <a href=\"" + escape(link) + "\">" + escape(linkText.empty() ? link : linkText) + "</a>";
  return out + "</figcaption></figure>";
}

std::string details(const std::string& summary, const std::string& body, bool open) {
  return std::string("<details") + (open ? " open" : "") + "><summary>" + summary + "</summary>" + body + "</details>\n";
}

std::string note(const std::string& text) { return "<p class=\"note\">" + escape(text) + "</p>\n"; }

std::string fileSafe(const std::string& name) {
  std::string out;
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' ? c : '_';
  return out.empty() ? "_" : out;
}

namespace {

// Inline, so the page needs nothing beside its images.
constexpr const char* kStyle = R"(
body { font: 14px/1.4 system-ui, sans-serif; margin: 1.5em; color: #222; background: #fafafa; }
h1 { margin-top: 0; } h2 { border-bottom: 1px solid #ccc; margin-top: 2em; } h3 { margin-bottom: .3em; }
nav ul { columns: 3; } .note { background: #fff4d6; border: 1px solid #e0c070; padding: .5em .8em; }
.row { display: flex; flex-wrap: wrap; gap: 1em; align-items: flex-start; }
figure { margin: 0; } figcaption { font-size: 12px; color: #555; max-width: 22em; }
figure img { width: 240px; image-rendering: pixelated; border: 1px solid #bbb; background: #fff; }
figure.chart img { width: 720px; image-rendering: auto; }
table { border-collapse: collapse; margin: .5em 0; font-size: 12px; background: #fff; }
th, td { border: 1px solid #ccc; padding: 2px 6px; vertical-align: top; } th { background: #eee; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
caption { text-align: left; font-weight: bold; padding: .2em 0; }
details { margin: .4em 0; } summary { cursor: pointer; font-weight: bold; }
details details { margin-left: 1.2em; } pre { font-size: 11px; background: #f0f0f0; padding: .4em; overflow-x: auto; }
.diff { color: #b00; }
)";

}  // namespace

std::string page(const std::string& title, const std::string& intro, const std::vector<Section>& sections) {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><link rel=\"icon\" href=\"data:,\"><title>" + escape(title) +
                    "</title><style>" + kStyle + "</style></head><body>\n<h1>" + escape(title) + "</h1>\n" + intro +
                    "<nav><ul>";
  for (const Section& s : sections) out += "<li><a href=\"#" + escape(s.id) + "\">" + escape(s.title) + "</a></li>";
  out += "</ul></nav>\n";
  for (const Section& s : sections)
    out += "<section id=\"" + escape(s.id) + "\"><h2>" + escape(s.title) + "</h2>\n" + s.html + "</section>\n";
  return out + "</body></html>\n";
}

}  // namespace report
