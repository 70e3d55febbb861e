// `raster trace` printed for people (trace_text.h).
#include "apps/trace/trace_text.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace cli {
namespace {

using OrderedJson = nlohmann::ordered_json;   // keys in the order written

std::string number(const OrderedJson& v) {
  if (v.is_null()) return "NaN";   // JSON has no NaN: nlohmann writes it as null
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v.get<double>());
  return text;
}

std::string tuple(const OrderedJson& values) {
  std::string text = "(";
  for (size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + number(values[i]);
  return text + ")";
}

// A stored value: a colour (with its bytes for RGBA8) or a depth code and its value.
std::string value(const OrderedJson& v, const std::string& format) {
  if (v.is_null()) return "(not in this image)";
  if (v.is_object()) return "z " + number(v["value"]) + " (code " + std::to_string(v["code"].get<uint64_t>()) + ")";
  std::string text = tuple(v);
  if (format == "RGBA8" && v.size() == 4) {
    text += " = bytes (";
    for (size_t c = 0; c < 4; ++c) {
      const double x = v[c].is_null() ? 0 : v[c].get<double>();
      text += (c ? ", " : "") + std::to_string(int(x * 255.0 + 0.5));
    }
    text += ")";
  }
  return text;
}

// "final (..), depth (..)" of a {target: value} object.
std::string values(const OrderedJson& byTarget, const OrderedJson& pass) {
  std::string text;
  for (auto it = byTarget.begin(); it != byTarget.end(); ++it) {
    std::string format;
    for (size_t k = 0; k < pass["targets"].size(); ++k)
      if (pass["targets"][k] == it.key()) format = pass["formats"][k];
    text += (text.empty() ? "" : "; ") + it.key() + " " + value(it.value(), format);
  }
  return text.empty() ? "-" : text;
}

void printLookup(std::ostream& out, const OrderedJson& s) {
  out << "      " << s["texture"].get<std::string>() << " at " << tuple(s["uv"]);
  if (s["kind"] == "compare") out << " ref " << number(s["ref"]);
  out << ", " << s["filter"].get<std::string>() << ":";
  for (const OrderedJson& t : s["texels"]) {
    out << " [" << t["x"].get<int>() << "," << t["y"].get<int>() << "] ";
    out << (t["value"].is_array() ? tuple(t["value"]) : number(t["value"]));
    if (t.contains("compare")) out << (t["compare"].get<bool>() ? " pass" : " fail");
    out << " w " << number(t["weight"]);
  }
  out << " -> " << (s["result"].is_array() ? tuple(s["result"]) : number(s["result"])) << "\n";
}

void printFragment(std::ostream& out, const OrderedJson& f, const OrderedJson& pass, size_t index) {
  out << "  #" << index << " draw " << f["draw"].get<int>() << " (" << f["program"].get<std::string>() << "), instance "
      << f["instance"].get<int>() << ", primitive " << f["primitive"].get<int>() << (f["clipped"].get<bool>() ? " (clipped)" : "")
      << (f["front_facing"].get<bool>() ? ", front" : ", back") << " facing, barycentrics " << tuple(f["barycentrics"]) << "\n";
  std::string what = f["covered"].get<bool>() ? "covered" : "not covered (a helper lane of its quad)";
  what += ", depth " + number(f["depth"]);
  if (!f["depth_code"].is_null()) what += " (code " + std::to_string(f["depth_code"].get<uint64_t>()) + ")";
  const std::string test = f["depth_test"];
  what += test == "off" ? ", depth test off" : ", early depth test " + test;
  if (f["region_fill"].get<bool>()) what += " (in a 16x16 region wholly inside: tested along rows)";
  what += f["written"].get<bool>() ? ", shaded and written" : f["shaded"].get<bool>() ? ", shaded as a helper, not written" : ", not shaded";
  out << "     " << what << "\n";
  if (f.contains("inputs")) {
    out << "     in: ";
    bool first = true;
    for (auto it = f["inputs"].begin(); it != f["inputs"].end(); ++it) {
      out << (first ? "" : "  ") << it.key() << " " << (it.value().is_array() ? tuple(it.value()) : number(it.value()));
      first = false;
    }
    out << "\n";
    const OrderedJson& samples = f["samples"];
    if (!samples.empty()) out << "     " << samples.size() << (samples.size() == 1 ? " lookup:\n" : " lookups:\n");
    for (size_t i = 0; i < samples.size() && i < kLookupsPrinted; ++i) printLookup(out, samples[i]);
    if (samples.size() > kLookupsPrinted) out << "      ... and " << samples.size() - kLookupsPrinted << " more (--json has every one)\n";
    out << "     out:";
    for (auto it = f["outputs"].begin(); it != f["outputs"].end(); ++it) out << " " << it.key() << " " << tuple(it.value());
    out << "\n";
  }
  if (f.contains("coarse")) {   // a coarse-shaded pass: one invocation per coarse pixel
    const OrderedJson& c = f["coarse"];
    out << "     coarse pixel " << c["size"][0].get<int>() << "x" << c["size"][1].get<int>() << " from texel ["
        << c["texel"][0].get<int>() << "," << c["texel"][1].get<int>() << "]";
    if (c.contains("lane")) {
      out << ": one invocation (lane " << c["lane"].get<int>() << ") at gl_FragCoord " << tuple(c["sample_position"]);
      if (c["broadcast_to"].empty()) out << ", a helper of its coarse quad: its outputs reached no pixel";
      else out << ", its outputs broadcast to " << c["broadcast_to"].size() << " of its " << c["size"][0].get<int>() * c["size"][1].get<int>()
               << " pixels:";
      for (const OrderedJson& p : c["broadcast_to"]) out << " [" << p[0].get<int>() << "," << p[1].get<int>() << "]";
    } else {
      out << ": no invocation of this triangle shaded it";
    }
    out << "\n";
  }
  out << "     before: " << values(f["before"], pass) << "\n";
  out << "     after:  " << values(f["after"], pass) << "\n";
}

}  // namespace

void printTrace(std::ostream& out, const OrderedJson& trace) {
  out << trace["scene"].get<std::string>() << ", pixel (" << trace["pixel"][0].get<int>() << ", " << trace["pixel"][1].get<int>()
      << ") of the " << trace["size"][0].get<int>() << "x" << trace["size"][1].get<int>() << " final image (row 0 at the top), t="
      << number(trace["time"]) << "\n";
  std::string methods;
  for (auto it = trace["methods"].begin(); it != trace["methods"].end(); ++it)
    methods += (methods.empty() ? "" : ", ") + it.key() + "=" + it.value().get<std::string>();
  out << "methods: " << methods << "\n";
  out << trace["passes"].size() << " passes traced, in the order they ran\n";
  for (const OrderedJson& pass : trace["passes"]) {
    std::string targets;
    for (size_t k = 0; k < pass["targets"].size(); ++k)
      targets += (k ? ", " : "") + pass["targets"][k].get<std::string>() + " " + pass["formats"][k].get<std::string>();
    std::string programs;
    for (const OrderedJson& p : pass["programs"]) programs += (programs.empty() ? "" : ", ") + p.get<std::string>();
    out << "\npass " << pass["pass"].get<int>() << (pass["label"].get<std::string>().empty() ? "" : " \"" + pass["label"].get<std::string>() + "\"")
        << ": " << (programs.empty() ? "no draws" : programs) << " into " << targets << " (" << pass["size"][0].get<int>() << "x"
        << pass["size"][1].get<int>() << "), pixel (" << pass["pixel"][0].get<int>() << ", " << pass["pixel"][1].get<int>()
        << ") = texel [" << pass["texel"][0].get<int>() << "," << pass["texel"][1].get<int>() << "]\n";
    out << "  why:    " << pass["why"].get<std::string>() << "\n";
    // Flushed, the usual mode, goes unsaid, as does a depth-only pass's (no colour to change).
    const bool writesColor = std::any_of(pass["formats"].begin(), pass["formats"].end(),
                                         [](const OrderedJson& f) { return !f.get<std::string>().starts_with("DEPTH"); });
    if (pass["denormals"] == "kept" && writesColor)
      out << "  denormals kept: llvmpipe's threads stop flushing them in a half-float draw's block that fails its depth test\n";
    if (!pass["clear"].is_null()) {
      out << "  clear:";
      if (pass["clear"].contains("color")) out << " color " << tuple(pass["clear"]["color"]);
      if (pass["clear"].contains("depth")) out << " depth " << number(pass["clear"]["depth"]);
      out << "\n";
    }
    out << "  start:  " << values(pass["start"], pass) << "\n";
    const OrderedJson& fragments = pass["fragments"];
    if (fragments.empty()) out << "  no fragment reached this pixel\n";
    for (size_t i = 0; i < fragments.size(); ++i) printFragment(out, fragments[i], pass, i);
    out << "  stored: " << values(pass["stored"], pass) << "\n";
    for (auto it = pass["matches_dump"].begin(); it != pass["matches_dump"].end(); ++it)
      out << "          " << it.key() << (it.value().get<bool>() ? " equals the frame's dump of it" : " DIFFERS from the frame's dump: "
                                                                    + values(OrderedJson{{it.key(), pass["dump"][it.key()]}}, pass)) << "\n";
    if (!pass["reference"].is_null() && !pass["reference"].empty()) {
      out << "  GL:     " << values(pass["reference"], pass) << "\n";
      for (auto it = pass["difference"].begin(); it != pass["difference"].end(); ++it)
        out << "          " << it.key() << " ours - GL " << tuple(it.value()) << "\n";
    }
  }
}

}  // namespace cli
