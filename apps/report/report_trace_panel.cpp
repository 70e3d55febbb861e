// One pixel's history as a collapsible panel (report_trace_panel.h).
#include "apps/report/report_trace_panel.h"

#include "apps/report/report_html.h"

namespace report {
namespace {

using nlohmann::json;

// The field `key` of an object, or null when the object or the field is missing.
json field(const json& object, const char* key) {
  return object.is_object() && object.contains(key) ? object.at(key) : json();
}

std::string text(const json& object, const char* key) { return escape(jsonText(field(object, key))); }

// "name = value" lines of an object ({"v_uv": [..], ...}), for a cell.
std::string namedValues(const json& values) {
  if (!values.is_object()) return escape(jsonText(values));
  std::string out;
  for (const auto& [name, value] : values.items())
    out += (out.empty() ? "" : "<br>") + escape(name + " = " + jsonText(value));
  return out.empty() ? "-" : out;
}

// True when some number in a difference value is not zero (arrays, nested).
bool nonZero(const json& value) {
  if (value.is_number()) return value.get<double>() != 0.0;
  if (value.is_array() || value.is_object())
    for (const json& v : value)
      if (nonZero(v)) return true;
  return false;
}

// The texture samples of a fragment: one line each, the 2x2 footprint as a table under it.
std::string samplesCell(const json& samples, const std::string& id) {
  if (!samples.is_array() || samples.empty()) return "-";
  std::string out;
  int index = 0;
  for (const json& s : samples) {
    const std::string line = text(s, "texture") + " at " + text(s, "uv") + " = " + text(s, "result");
    const json texels = field(s, "texels");
    if (!texels.is_array() || texels.empty()) {
      out += "<div>" + line + "</div>";
      continue;
    }
    Table t{id + "-s" + std::to_string(index), "", {"x", "y", "value", "weight"}, {}};
    for (const json& texel : texels)
      t.rows.push_back({text(texel, "x"), text(texel, "y"), text(texel, "value"), text(texel, "weight")});
    out += details(line, t.html());
    ++index;
  }
  return out;
}

std::string fragmentsTable(const json& fragments, const std::string& id) {
  if (!fragments.is_array() || fragments.empty()) return "<p>No fragment reached this pixel in this pass.</p>";
  Table t{id + "-fragments", "fragments, in the order they reached the pixel",
          {"#", "draw", "program", "instance", "primitive", "barycentrics", "depth", "depth test", "helper", "written",
           "inputs", "outputs", "samples", "before", "after"},
          {}};
  int index = 0;
  for (const json& f : fragments) {
    const std::string fid = id + "-f" + std::to_string(index);
    t.rows.push_back({escape(std::to_string(index)), text(f, "draw"), text(f, "program"), text(f, "instance"),
                      text(f, "primitive"), text(f, "barycentrics"), text(f, "depth"), text(f, "depth_test"),
                      text(f, "helper"), text(f, "written"), namedValues(field(f, "inputs")),
                      namedValues(field(f, "outputs")), samplesCell(field(f, "samples"), fid),
                      namedValues(field(f, "before")), namedValues(field(f, "after"))});
    ++index;
  }
  return t.html();
}

// Stored, GL and difference per target of the pass.
std::string valuesTable(const json& pass, const std::string& id) {
  const json stored = field(pass, "stored"), reference = field(pass, "reference"), difference = field(pass, "difference");
  if (!stored.is_object() || stored.empty()) return "";
  Table t{id + "-values", "the pixel after the pass", {"target", "stored", "GL (llvmpipe)", "difference"}, {}};
  for (const auto& [target, value] : stored.items()) {
    const json diff = field(difference, target.c_str());
    const std::string diffCell = escape(jsonText(diff));
    t.rows.push_back({escape(target), escape(jsonText(value)), escape(jsonText(field(reference, target.c_str()))),
                      nonZero(diff) ? "<td class=\"diff\">" + diffCell + "</td>" : diffCell});
  }
  return t.html();
}

std::string listText(const json& list) {
  if (!list.is_array()) return escape(jsonText(list));
  std::string out;
  for (const json& item : list) out += (out.empty() ? "" : ", ") + jsonText(item);
  return escape(out);
}

}  // namespace

std::string tracePanel(const json& trace, const std::string& id) {
  const json pixel = field(trace, "pixel");
  const json passes = field(trace, "passes");
  std::string body = "<p>" + text(trace, "scene") + " at " + text(trace, "size") + ", t=" + text(trace, "time");
  if (field(trace, "methods").is_object()) body += "; methods: " + namedValues(field(trace, "methods"));
  body += "</p>\n";
  int index = 0;
  std::string finalLine;
  if (passes.is_array()) {
    for (const json& pass : passes) {
      const std::string pid = id + "-p" + std::to_string(index++);
      const json fragments = field(pass, "fragments");
      const size_t count = fragments.is_array() ? fragments.size() : 0;
      const std::string summary = "pass " + text(pass, "pass") + ": " + listText(field(pass, "programs")) + " &rarr; " +
                                  listText(field(pass, "targets")) + ", pixel " + text(pass, "pixel") + " (" +
                                  text(pass, "why") + "), " + std::to_string(count) + " fragment" +
                                  (count == 1 ? "" : "s");
      body += details(summary, fragmentsTable(fragments, pid) + valuesTable(pass, pid));
      // The last pass's final-image line goes into the panel's summary.
      const json stored = field(pass, "stored");
      if (stored.is_object() && stored.contains("final"))
        finalLine = "; final: ours " + escape(jsonText(stored.at("final"))) + ", GL " +
                    escape(jsonText(field(field(pass, "reference"), "final"))) + ", difference " +
                    escape(jsonText(field(field(pass, "difference"), "final")));
    }
  }
  const std::string summary = "pixel " + escape(jsonText(pixel)) + ": " + std::to_string(index) + " pass" +
                              (index == 1 ? "" : "es") + finalLine;
  return "<div class=\"trace\" id=\"" + escape(id) + "\">" + details(summary, body) + "</div>\n";
}

}  // namespace report
