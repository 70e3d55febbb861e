// `raster trace`: which passes to trace, the renders that trace them, and the trace as JSON
// (trace.h). trace_text.cpp prints the same JSON for people.
#include "apps/trace/trace.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <set>

#include <nlohmann/json.hpp>

#include "apps/common/sides.h"
#include "apps/trace/trace_text.h"
#include "io/output_file.h"
#include "raster/methods.h"
#include "raster/pixel_history.h"
#include "raster/texture/format.h"
#include "backends/backends.h"
#include "scenes/registry.h"

namespace cli {
namespace {

using OrderedJson = nlohmann::ordered_json;   // keys in the order written
using raster::FragmentRecord;
using raster::PassHistory;
using raster::PixelHistory;
using raster::PixelValue;
using raster::Texture;

// ---- which passes, at which pixel -------------------------------------------------------

struct Probe {
  int x = 0, y = 0;   // column and memory row
  std::string why;
};

// The fragment whose lookups a pass's value came from: its last written one, else its last
// shaded one.
const FragmentRecord* lastFragment(const PassHistory& pass) {
  for (auto it = pass.fragments.rbegin(); it != pass.fragments.rend(); ++it)
    if (it->written) return &*it;
  for (auto it = pass.fragments.rbegin(); it != pass.fragments.rend(); ++it)
    if (it->shaded) return &*it;
  return nullptr;
}

bool writes(const PassHistory& pass, const Texture* texture) {
  return pass.depth == texture || std::find(pass.colors.begin(), pass.colors.end(), texture) != pass.colors.end();
}

std::string passName(const PassHistory& pass) {
  return "pass " + std::to_string(pass.pass) + (pass.label.empty() ? "" : " (" + pass.label + ")");
}

std::string textureName(const Texture* texture) { return texture->label.empty() ? "an unnamed texture" : texture->label; }

// New probes from the lookups of every traced pass: for each texture its last fragment
// sampled, the pass before it that last wrote that texture, at the texel its middle lookup
// of that texture weighted most. Returns whether any probe was added.
bool addSampledProbes(const PixelHistory& history, std::map<int, Probe>& probes) {
  bool added = false;
  for (auto pass = history.passes.rbegin(); pass != history.passes.rend(); ++pass) {
    if (!pass->probed) continue;
    const FragmentRecord* fragment = lastFragment(*pass);
    if (!fragment) continue;
    std::vector<const Texture*> textures;   // in the order the shader first read them
    for (const auto& sample : fragment->samples)
      if (std::find(textures.begin(), textures.end(), sample.texture) == textures.end()) textures.push_back(sample.texture);
    for (const Texture* texture : textures) {
      const PassHistory* writer = nullptr;
      for (int p = pass->pass - 1; p >= 0 && !writer; --p)
        if (writes(history.passes[size_t(p)], texture)) writer = &history.passes[size_t(p)];
      if (!writer || probes.count(writer->pass)) continue;
      std::vector<const raster::sampling::SampleRecord*> lookups;
      for (const auto& sample : fragment->samples)
        if (sample.texture == texture) lookups.push_back(&sample);
      const auto& lookup = *lookups[lookups.size() / 2];
      const auto& texel = *std::max_element(lookup.texels, lookup.texels + std::max(lookup.texelCount, 1),
                                            [](const auto& a, const auto& b) { return a.weight < b.weight; });
      char why[256];
      std::snprintf(why, sizeof why, "%s of %s at (%.6g, %.6g), %s", lookups.size() > 1 ? "the middle lookup" : "the lookup",
                    passName(*pass).c_str(), lookup.s, lookup.t,
                    lookup.texelCount > 1 ? "its texel of largest weight" : "its texel");
      probes[writer->pass] = {texel.x, texel.y, std::string("read by ") + why};
      added = true;
    }
  }
  return added;
}

// ---- values -----------------------------------------------------------------------------

// The target names of a pass's attachments, colour ones then depth: each attachment's
// texture label, except that a pass labelled with a target's name stands for its first
// attachment (hdr's bloom passes: one texture, read back once per pass).
std::vector<std::string> attachmentNames(const PassHistory& pass, const std::set<std::string>& targets) {
  std::vector<std::string> names;
  for (const Texture* color : pass.colors) names.push_back(color->label);
  if (pass.depth) names.push_back(pass.depth->label);
  if (!names.empty() && targets.count(pass.label)) names[0] = pass.label;
  return names;
}

// A depth code and the value it stands for, code / (2^bits - 1).
OrderedJson depthValue(uint32_t code, int bits) {
  return OrderedJson{{"code", code}, {"value", double(code) / double((uint64_t(1) << bits) - 1)}};
}

OrderedJson colorValue(const std::array<float, 4>& rgba) { return OrderedJson::array({rgba[0], rgba[1], rgba[2], rgba[3]}); }

OrderedJson pixelJson(const PixelValue& value, const PassHistory& pass, const std::vector<std::string>& names) {
  OrderedJson out = OrderedJson::object();
  for (size_t k = 0; k < value.colors.size(); ++k) out[names[k]] = colorValue(value.colors[k]);
  if (value.hasDepth) out[names.back()] = depthValue(value.depthCode, pass.depth->depthBits());
  return out;
}

// A target image's value at a pass's probe, in the same form as pixelJson.
OrderedJson imageValue(const scenes::ImageData& image, const PassHistory& pass) {
  const int row = pass.flipY ? pass.y : pass.height - 1 - pass.y;   // images are top row first
  if (image.width != pass.width || image.height != pass.height) return nullptr;
  const size_t texel = size_t(row) * size_t(image.width) + size_t(pass.x);
  if (!image.depth.empty()) return depthValue(image.depth[texel], image.depthBits);
  OrderedJson rgba = OrderedJson::array();
  for (int c = 0; c < 4; ++c) {
    if (!image.rgba8.empty()) rgba.push_back(float(image.rgba8[texel * 4 + size_t(c)]) * float(1.0 / 255.0));
    else rgba.push_back(c < image.channels ? image.floats[texel * size_t(image.channels) + size_t(c)] : 1.0f);
  }
  return rgba;
}

// Equal values, a NaN equal to a NaN (a NaN pixel is stored and dumped alike).
bool sameValue(const OrderedJson& a, const OrderedJson& b) {
  if (a.is_number_float() || b.is_number_float()) {
    if (!a.is_number() || !b.is_number()) return false;
    const double x = a.get<double>(), y = b.get<double>();
    return x == y || (std::isnan(x) && std::isnan(y));
  }
  if (a.is_array() && b.is_array()) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
      if (!sameValue(a[i], b[i])) return false;
    return true;
  }
  if (a.is_object() && b.is_object()) return a.contains("code") && b.contains("code") && a["code"] == b["code"];
  return a == b;
}

std::string formatName(raster::TexelFormat format) {
  switch (format) {
    case raster::TexelFormat::RGBA8: return "RGBA8";
    case raster::TexelFormat::RGBA16F: return "RGBA16F";
    case raster::TexelFormat::RGB16F: return "RGB16F";
    case raster::TexelFormat::RGBA32F: return "RGBA32F";
    case raster::TexelFormat::Depth16: return "DEPTH16";
    case raster::TexelFormat::Depth24: return "DEPTH24";
  }
  return "?";
}

OrderedJson difference(const OrderedJson& ours, const OrderedJson& reference) {
  if (ours.is_object()) return OrderedJson::array({double(ours["code"].get<uint64_t>()) - double(reference["code"].get<uint64_t>())});
  OrderedJson out = OrderedJson::array();
  for (size_t c = 0; c < ours.size(); ++c) out.push_back(ours[c].get<double>() - reference[c].get<double>());
  return out;
}

// ---- shader names from the GLSL sources --------------------------------------------------

struct ShaderNames {
  std::vector<std::string> inputs;    // one per interpolated float: "v_uv.x"
  std::vector<std::string> outputs;   // per location
};

ShaderNames shaderNames(const std::string& program, size_t varyingFloats, size_t outputs) {
  ShaderNames names;
  std::ifstream file(scenes::programFiles(program).fragment);
  const std::regex declaration(R"(^\s*(?:layout\s*\(\s*location\s*=\s*(\d+)\s*\)\s*)?(in|out)\s+(float|vec2|vec3|vec4)\s+(\w+)\s*;)");
  std::map<int, std::string> outputAt;
  int nextOutput = 0;
  for (std::string line; std::getline(file, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, declaration)) continue;
    const std::string type = m[3], name = m[4];
    if (m[2] == "out") {
      outputAt[m[1].matched ? std::stoi(m[1]) : nextOutput] = name;
      ++nextOutput;
      continue;
    }
    const int size = type == "float" ? 1 : type[3] - '0';
    for (int c = 0; c < size; ++c) names.inputs.push_back(size == 1 ? name : name + "." + "xyzw"[c]);
  }
  if (names.inputs.size() != varyingFloats) {   // not what the port interpolates: plain indices
    names.inputs.clear();
    for (size_t v = 0; v < varyingFloats; ++v) names.inputs.push_back("varying[" + std::to_string(v) + "]");
  }
  for (size_t k = 0; k < outputs; ++k)
    names.outputs.push_back(outputAt.count(int(k)) ? outputAt[int(k)] : "output[" + std::to_string(k) + "]");
  return names;
}

// Inputs grouped back into the GLSL's vectors: {"v_uv": [x, y], ...}.
OrderedJson inputsJson(const FragmentRecord& fragment, const ShaderNames& names) {
  OrderedJson inputs = OrderedJson::object();
  inputs["gl_FragCoord"] = OrderedJson::array({fragment.fragCoord[0], fragment.fragCoord[1], fragment.fragCoord[2], fragment.fragCoord[3]});
  for (size_t v = 0; v < fragment.varyings.size(); ++v) {
    const std::string& name = names.inputs[v];
    const size_t dot = name.find('.');
    const std::string base = dot == std::string::npos ? name : name.substr(0, dot);
    if (dot == std::string::npos) inputs[base] = fragment.varyings[v];
    else inputs[base].push_back(fragment.varyings[v]);
  }
  return inputs;
}

OrderedJson sampleJson(const raster::sampling::SampleRecord& sample) {
  OrderedJson texels = OrderedJson::array();
  for (int k = 0; k < sample.texelCount; ++k) {
    const auto& texel = sample.texels[k];
    OrderedJson t{{"x", texel.x}, {"y", texel.y}};
    if (sample.compare) t["value"] = texel.value[0];
    else t["value"] = OrderedJson::array({texel.value[0], texel.value[1], texel.value[2], texel.value[3]});
    t["weight"] = texel.weight;
    if (sample.compare) t["compare"] = texel.compare == 1;
    texels.push_back(t);
  }
  OrderedJson out{{"texture", textureName(sample.texture)},
           {"kind", sample.compare ? "compare" : "color"},
           {"uv", OrderedJson::array({sample.s, sample.t})}};
  if (sample.compare) out["ref"] = sample.ref;
  out["lod"] = 0;   // no texture of the scenes has mipmaps: every lookup reads level 0
  out["filter"] = sample.filter;
  out["weights"] = OrderedJson::array({sample.weightS, sample.weightT});
  out["texels"] = texels;
  if (sample.compare) {
    out["result"] = sample.result[0];
    out["explained"] = sample.explained[0];
  } else {
    out["result"] = OrderedJson::array({sample.result[0], sample.result[1], sample.result[2], sample.result[3]});
    out["explained"] = OrderedJson::array({sample.explained[0], sample.explained[1], sample.explained[2], sample.explained[3]});
  }
  return out;
}

OrderedJson fragmentJson(const FragmentRecord& f, const PassHistory& pass, const std::vector<std::string>& names,
                  std::map<std::string, ShaderNames>& shaderNameCache) {
  const std::string& program = pass.programs[f.draw];
  OrderedJson out{{"draw", f.draw}, {"program", program}, {"instance", f.instance}, {"primitive", f.primitive},
           {"clipped", f.clipped}, {"front_facing", f.frontFacing},
           {"barycentrics", OrderedJson::array({f.barycentric[0], f.barycentric[1], f.barycentric[2]})},
           {"covered", f.covered}, {"depth", f.z}};
  out["depth_code"] = pass.depth ? OrderedJson(f.depthCode) : OrderedJson(nullptr);
  out["depth_test"] = !f.depthTested ? "off" : f.depthPassed ? "passed" : "failed";
  out["early"] = f.earlyDepth;
  out["region_fill"] = f.regionFill;
  out["shaded"] = f.shaded;
  out["helper"] = f.helper;
  out["discarded"] = f.discarded;
  out["written"] = f.written;
  if (f.shaded) {
    auto cached = shaderNameCache.find(program);
    if (cached == shaderNameCache.end())
      cached = shaderNameCache.emplace(program, shaderNames(program, f.varyings.size(), f.outputs.size())).first;
    out["inputs"] = inputsJson(f, cached->second);
    OrderedJson outputs = OrderedJson::object();
    for (size_t k = 0; k < f.outputs.size(); ++k) outputs[cached->second.outputs[k]] = colorValue(f.outputs[k]);
    out["outputs"] = outputs;
    OrderedJson samples = OrderedJson::array();
    for (const auto& sample : f.samples) samples.push_back(sampleJson(sample));
    out["samples"] = samples;
  }
  // A coarse pass (methods.h, `shading`): the invocation behind the pixel and its coarse pixel.
  if (f.coarseWidth > 1 || f.coarseHeight > 1) {
    OrderedJson coarse{{"size", OrderedJson::array({f.coarseWidth, f.coarseHeight})},
                       {"texel", OrderedJson::array({f.coarseX, f.coarseY})}};
    if (f.shaded) {
      coarse["lane"] = f.lane;
      coarse["sample_position"] = OrderedJson::array({f.fragCoord[0], f.fragCoord[1]});
      OrderedJson broadcast = OrderedJson::array();
      for (const auto& p : f.broadcast) broadcast.push_back(OrderedJson::array({p[0], p[1]}));
      coarse["broadcast_to"] = broadcast;
    }
    out["coarse"] = coarse;
  }
  out["before"] = pixelJson(f.before, pass, names);
  out["after"] = pixelJson(f.after, pass, names);
  return out;
}

OrderedJson clearJson(const raster::ClearValues& clear) {
  if (!clear.color && !clear.depth) return nullptr;
  OrderedJson out = OrderedJson::object();
  if (clear.color) out["color"] = OrderedJson::array({clear.colorValue[0], clear.colorValue[1], clear.colorValue[2], clear.colorValue[3]});
  if (clear.depth) out["depth"] = clear.depthValue;
  return out;
}

using TargetMap = std::map<std::string, const scenes::ImageData*>;

TargetMap byName(const std::vector<scenes::Target>& targets) {
  TargetMap map;
  for (const scenes::Target& t : targets) map[t.name] = &t.image;
  return map;
}

std::pair<int, int> parsePixel(const std::string& text, int width, int height) {
  const size_t comma = text.find(',');
  const auto x = comma == std::string::npos ? std::nullopt : parseWholeNumber(text.substr(0, comma));
  const auto y = comma == std::string::npos ? std::nullopt : parseWholeNumber(text.substr(comma + 1));
  if (!x || !y) throw UsageError("--pixel: '" + text + "' is not X,Y (two whole numbers, row 0 at the top)");
  if (*x >= uint64_t(width) || *y >= uint64_t(height))
    throw UsageError("--pixel: " + text + " is outside the " + std::to_string(width) + "x" + std::to_string(height) +
                     " image (X 0.." + std::to_string(width - 1) + ", Y 0.." + std::to_string(height - 1) + ")");
  return {int(*x), int(*y)};
}

}  // namespace

void addTraceOptions(CLI::App& command, TraceArgs& args) {
  addFrameOptions(command, args);
  // Shared with render and compare, where it works; here the help says it is refused (below).
  command.get_option("--float-final")->description("Refused: the pixel history follows the window's final image (use render or compare with it)");
  command.add_option("--pixel", args.pixel, "The pixel of the final image, row 0 at the top")->required()->type_name("X,Y");
  command.add_option("--json", args.json, "Also write the trace as JSON here")->type_name("FILE");
  command.add_flag("--no-reference", args.noReference, "Leave out GL's values (no llvmpipe render)");
}

int runTrace(const TraceArgs& args) {
  const Frame frame = validateFrame(args);
  if (frame.floatFinal)
    throw UsageError("--float-final: the pixel history follows the window's final image; use render or compare with it");
  const auto [pixelX, pixelY] = parsePixel(args.pixel, frame.width, frame.height);
  if (!args.json.empty()) checkOutputFile("--json", args.json);
  if (!args.noReference) scenes::checkGalliumEnvironment();

  // This pipeline's frame, traced: a first render finds the passes, then each round adds
  // the passes whose textures the traced ones read.
  const scenes::SceneOptions options = sceneOptions(frame);
  std::unique_ptr<scenes::Scene> scene = scenes::makeScene(frame.scene, options);
  const raster::ScopedMethods methods(frame.methods);
  std::unique_ptr<scenes::Backend> backend = scenes::makeRasterBackend(frame.threads, frame.scalar);
  if (!frame.quiet) std::cerr << "tracing " << frame.scene << " at pixel " << args.pixel << ", " << sizeAndTime(frame) << " ..." << std::endl;
  backend->resizeDefaultFramebuffer(frame.width, frame.height);
  scene->setup(*backend);
  PixelHistory history;
  std::map<int, Probe> probes;
  auto render = [&] {
    history.passes.clear();
    history.probes.clear();
    for (const auto& [pass, probe] : probes) history.probes[pass] = {probe.x, probe.y};
    scenes::setPixelHistory(*backend, &history);
    scene->renderFrame(*backend, frame.time);
    scenes::setPixelHistory(*backend, nullptr);   // flushes the last pass first
  };
  render();
  for (const PassHistory& pass : history.passes)
    for (const Texture* color : pass.colors)
      if (color->label == "final") probes[pass.pass] = {pixelX, pass.flipY ? pixelY : pass.height - 1 - pixelY, "the pixel asked for"};
  if (probes.empty()) throw std::runtime_error("no pass of " + frame.scene + " writes the final image");
  for (size_t round = 0; round <= history.passes.size(); ++round) {
    render();
    if (!addSampledProbes(history, probes)) break;
  }
  const std::vector<scenes::Target> dumps = scene->readTargets(*backend);   // untraced: history is off
  std::optional<Side> reference;
  if (!args.noReference) reference = renderSide(frame, "llvmpipe");

  // The trace as JSON.
  std::set<std::string> targetNames;
  for (const scenes::Target& t : dumps) targetNames.insert(t.name);
  const TargetMap dumpAt = byName(dumps);
  const TargetMap referenceAt = reference ? byName(reference->targets) : TargetMap{};
  // The last pass writing each target name is the one its dump holds.
  std::map<std::string, int> lastWriter;
  for (const PassHistory& pass : history.passes)
    for (const std::string& name : attachmentNames(pass, targetNames)) lastWriter[name] = pass.pass;

  OrderedJson trace{{"scene", frame.scene}, {"pixel", OrderedJson::array({pixelX, pixelY})},
             {"size", OrderedJson::array({frame.width, frame.height})}, {"time", frame.time}};
  OrderedJson methodNames = OrderedJson::object();
  for (const auto& [step, name] : raster::methodNames(frame.methods)) methodNames[step] = name;
  trace["methods"] = methodNames;
  bool allMatch = true;
  OrderedJson passes = OrderedJson::array();
  std::map<std::string, ShaderNames> shaderNameCache;
  for (const PassHistory& pass : history.passes) {
    if (!pass.probed) continue;
    const std::vector<std::string> names = attachmentNames(pass, targetNames);
    const int imageRow = pass.flipY ? pass.y : pass.height - 1 - pass.y;
    OrderedJson formats = OrderedJson::array();
    for (const Texture* color : pass.colors) formats.push_back(formatName(color->format));
    if (pass.depth) formats.push_back(formatName(pass.depth->format));
    OrderedJson p{{"pass", pass.pass}, {"label", pass.label}, {"programs", pass.programs}, {"targets", names}, {"formats", formats},
           {"size", OrderedJson::array({pass.width, pass.height})}, {"pixel", OrderedJson::array({pass.x, imageRow})},
           {"texel", OrderedJson::array({pass.x, pass.y})}, {"why", probes[pass.pass].why}, {"clear", clearJson(pass.clear)},
           {"denormals", pass.keepsDenormals ? "kept" : "flushed"}};
    OrderedJson fragments = OrderedJson::array();
    for (const FragmentRecord& f : pass.fragments) fragments.push_back(fragmentJson(f, pass, names, shaderNameCache));
    p["fragments"] = fragments;
    p["start"] = pixelJson(pass.afterClear, pass, names);
    p["stored"] = pixelJson(pass.stored, pass, names);
    OrderedJson dump = OrderedJson::object(), matches = OrderedJson::object(), ref = OrderedJson::object(), diff = OrderedJson::object();
    for (const std::string& name : names) {
      if (lastWriter[name] != pass.pass) continue;   // a later pass overwrote what the dump holds
      if (dumpAt.count(name)) {
        dump[name] = imageValue(*dumpAt.at(name), pass);
        matches[name] = sameValue(dump[name], p["stored"][name]);
        allMatch = allMatch && matches[name].get<bool>();
      }
      if (referenceAt.count(name)) {
        ref[name] = imageValue(*referenceAt.at(name), pass);
        if (!ref[name].is_null()) diff[name] = difference(p["stored"][name], ref[name]);
      }
    }
    p["dump"] = dump;
    p["matches_dump"] = matches;
    p["reference"] = reference ? ref : OrderedJson(nullptr);
    p["difference"] = reference ? diff : OrderedJson(nullptr);
    passes.push_back(p);
  }
  trace["stored_matches_dumps"] = allMatch;
  trace["passes"] = passes;

  printTrace(std::cout, trace);
  if (!args.json.empty()) {
    compare::writeOutputFile(args.json, trace.dump(1) + "\n");
    std::cout << "wrote " << args.json << std::endl;
  }
  if (!allMatch) {
    std::cerr << "raster: a traced pass stored a value that differs from its target dump (an internal error)" << std::endl;
    return 1;
  }
  return 0;
}

}  // namespace cli
