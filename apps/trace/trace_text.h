// The pixel history of `raster trace` for people: the trace's JSON (trace.h) printed pass by
// pass, fragment by fragment. Printed from the JSON, so the two never disagree.
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

namespace cli {

// Lookups printed per fragment; the JSON has every one.
constexpr size_t kLookupsPrinted = 6;

void printTrace(std::ostream& out, const nlohmann::ordered_json& trace);

}  // namespace cli
