// The method sets (raster/methods.h) the pipeline's equality checks run under, read from
// the catalog: a method added to a step is in them without a line here.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "raster/methods.h"

namespace testing_support {

// gl, every set that differs from gl in one step (each other method of each step), then
// the presets that are none of those: each set once.
inline std::vector<raster::MethodSet> everyMethodSet() {
  std::vector<raster::MethodSet> sets{raster::MethodSet{}};
  auto add = [&](const raster::MethodSet& set) {
    if (std::find(sets.begin(), sets.end(), set) == sets.end()) sets.push_back(set);
  };
  for (const raster::StepInfo& step : raster::methodCatalog())
    for (const raster::MethodInfo& method : step.methods) {
      raster::MethodSet set;
      raster::setMethod(set, step.name, method.name);
      add(set);
    }
  for (const std::string& preset : raster::presetNames()) add(raster::presetMethods(preset));
  return sets;
}

}  // namespace testing_support
