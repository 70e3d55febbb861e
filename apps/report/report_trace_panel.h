// The pixel-history panel of the report: one pixel's `raster trace --json` output as a
// collapsible panel, pass by pass: the fragments that reached the pixel (draw, primitive,
// barycentrics, depth and its test, helper lane, the shader's inputs and outputs, the
// texture samples with their texels), then the value stored in each target, GL's value and
// the difference where the trace knows them.
//
// The trace's schema (written by `raster trace`; fields may be added, none removed):
//   {"scene", "pixel": [x, y], "size": [w, h], "time", "methods": {step: name},
//    "passes": [{"pass", "programs": [...], "targets": [...], "size", "pixel", "why",
//                "fragments": [{"draw", "program", "instance", "primitive", "barycentrics",
//                               "depth", "depth_test", "helper", "written", "inputs", "outputs",
//                               "samples": [{"texture", "uv", "result", "texels": [{x, y, value, weight}]}],
//                               "before", "after"}],
//                "stored": {target: value}, "reference": {target: value} | null,
//                "difference": {target: value} | null}]}
// A field that is missing shows as "-": the panel never fails on a trace it cannot fully read.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace report {

// The panel (HTML) of one trace. `id` names it (and prefixes its tables' ids).
std::string tracePanel(const nlohmann::json& trace, const std::string& id);

}  // namespace report
