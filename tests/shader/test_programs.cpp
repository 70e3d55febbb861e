// The tests' probe programs (shaders_cpp/test/): registered here, in the test binary, so
// the production registry holds only the scenes' programs and `raster soup`'s
// (test/passthrough, registered by scenes/soup/soup_check.cpp).
#include "scenes/program_registry.h"
#include "scenes/registry.h"
#include "shaders_cpp/test/color_lookup.h"
#include "shaders_cpp/test/derivatives.h"
#include "shaders_cpp/test/instanced.h"
#include "shaders_cpp/test/math_probe.h"
#include "shaders_cpp/test/mrt.h"
#include "shaders_cpp/test/shadow_lookup.h"
#include "shaders_cpp/test/uniform_array.h"

namespace {

using scenes::programEntry;

// Runs before main (doctest's), so every test finds them.
[[maybe_unused]] const bool registered = [] {
  for (scenes::ProgramEntry& entry :
       std::vector{programEntry<shaders::test::ColorLookup>(),
                   programEntry<shaders::test::Derivatives>(), programEntry<shaders::test::Instanced>(),
                   programEntry<shaders::test::ShadowLookup>(), programEntry<shaders::test::MathProbe>(),
                   programEntry<shaders::test::Mrt>(), programEntry<shaders::test::UniformArray>()})
    scenes::registerProgram(std::move(entry));
  return true;
}();

}  // namespace
