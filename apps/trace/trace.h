// `raster trace SCENE --pixel X,Y`: the pixel history of one pixel of the final image, pass
// by pass, from inside this pipeline (raster/pixel_history.h records it).
//
// Which passes: every pass that writes the final image at (X, Y), then, following the
// texture lookups of each traced pass's last written fragment back to the pass that wrote
// the sampled texture, that pass at the texel the lookup weighted most: the shadow map
// texel a pixel's PCF centres on, the G-buffer texels the lighting pass reads, each bloom
// mip the composite reads through the up and down chain. Each round of that search renders
// the frame again with one more set of probes (the frame is deterministic), so a trace
// costs a few frames.
//
// Per traced pass it prints (and writes as JSON with --json) every fragment that reached
// the pixel, in order: draw, instance, primitive, barycentrics, depth and its early test,
// helper lanes, the shader's named inputs and outputs (names from the GLSL sources), every
// texture lookup with its footprint (texels, weights, compare results), and the pixel
// before and after. Each pass ends with the value it stored, checked against the frame's
// target dump, and GL's (llvmpipe's) value of the same target and the difference.
//
// JSON (--json FILE):
//   {"scene", "pixel": [x, y], "size": [w, h], "time", "methods": {step: name},
//    "stored_matches_dumps": bool,
//    "passes": [{"pass", "label", "programs", "targets", "formats", "size",
//                "pixel" (image: row 0 = top),
//                "texel" (memory row), "why", "clear", "denormals" ("kept" | "flushed":
//                  the fragment stage's, raster/simd/gl_math.h),
//                "fragments": [{"draw", "program", "instance", "primitive", "clipped",
//                               "front_facing", "barycentrics", "covered", "depth",
//                               "depth_code", "depth_test" ("passed" | "failed" | "off"),
//                               "early", "region_fill", "shaded", "helper", "discarded",
//                               "written", "inputs": {name: [..]}, "outputs": {name: [..]},
//                               "samples": [{"texture", "kind", "uv", "ref", "lod", "filter",
//                                            "weights", "texels": [{"x", "y", "value",
//                                            "weight", "compare"}], "result", "explained"}],
//                               "coarse" (only in a pass shaded at a coarse rate, --method
//                                 shading=RATE): {"size": [w, h], "texel": [x, y] (the coarse
//                                 pixel's first texel), and where an invocation of this
//                                 triangle shaded it: "lane", "sample_position" (its
//                                 gl_FragCoord.xy: the coarse pixel's centre), "broadcast_to":
//                                 [[x, y], ..] (the texels its outputs were written to)},
//                               "before": {target: value}, "after": {target: value}}],
//                "start": {target: value}, "stored": {target: value},
//                "dump": {target: value}, "matches_dump": {target: bool},
//                "reference": {target: value} | null, "difference": {target: [..]} | null}]}
// A colour value is [r, g, b, a] as stored (unorm8 / 255, half, float); a depth value is
// {"code", "value"}.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "apps/common/cli_options.h"

namespace cli {

struct TraceArgs : FrameArgs {
  std::string pixel;          // X,Y in the final image, row 0 at the top
  std::string json;           // empty: no JSON file
  bool noReference = false;   // leave GL's values out (no llvmpipe render)
};

void addTraceOptions(CLI::App& command, TraceArgs& args);
int runTrace(const TraceArgs& args);

}  // namespace cli
