// Texture lookups as pixel history sees them: each lookup one traced lane made, with the
// texels of its footprint, their weights and (for shadow lookups) their compare results.
//
// Recording is switched on per thread, only while the pixel history's own lane group is
// shaded (tile/trace_tile.cpp). Only the reference lookups of sampler.h record: the traced
// tile is shaded with ScalarLanes, whose lookups are those, so the vector samplers carry no
// check at all. The footprint is worked out again by explain*() with the arithmetic of the
// lookup itself (sample_color.cpp, sample_compare.cpp), and the record keeps both results,
// so a trace shows at once if the explanation ever parted from the lookup.
#pragma once

#include <vector>

#include "raster/texture/texture.h"

namespace raster::sampling {

// One texel of a footprint.
struct FootprintTexel {
  int x = 0, y = 0;       // texel column and memory row (row 0 = GL's t = 0)
  float value[4] = {};    // as the filter reads it (unorm8 / half / float decoded; depth as float)
  float weight = 0.0f;    // its share of the result: the product of the axis weights
  int compare = -1;       // shadow lookups: 1 if ref <= texel passed, 0 if not; -1 otherwise
};

// One lookup of a traced lane.
struct SampleRecord {
  const Texture* texture = nullptr;
  bool compare = false;      // a sampler2DShadow lookup (texture(shadow, vec3(uv, ref)))
  float s = 0, t = 0;        // the coordinates the shader passed
  float ref = 0;             // compare lookups: the reference, as passed (clamped to [0, 1] inside)
  float result[4] = {};      // what the lookup returned to the shader (compare: result[0])
  // The footprint, worked out again with the lookup's arithmetic.
  const char* filter = "";   // which arithmetic: "unorm8 fixed point", "float", "nearest", "compare"
  float weightS = 0, weightT = 0;   // the axis weights of the second texel column and row
  int texelCount = 0;
  FootprintTexel texels[4];
  float explained[4] = {};   // the result recomputed from the footprint; equals `result`
};

// The lookups of one lane while it is traced.
struct SampleTrace {
  int lane = 0;                          // which lane of the group is the traced pixel
  std::vector<SampleRecord> records;
};

// The trace recording on this thread, or null (the normal case).
inline thread_local SampleTrace* tActiveSampleTrace = nullptr;

// A colour texel (column x, memory row y) as the pipeline stores it, decoded: unorm8 / 255,
// the half's value, or the float. What a footprint shows, and what pixel history reads.
void colorTexelValue(const Texture& texture, int x, int y, float out[4]);

// The footprint of a colour lookup (sampleColor) and of a compare lookup
// (compareClamp, either compare method): fills a record's filter, weights, texels and
// explained result.
void explainColor(const Texture& texture, SampleRecord& record);
void explainCompare(const Texture& depth, SampleRecord& record);

// Called by the reference lookups for every lane group: records the traced lane's lookup
// when a trace is active on this thread.
inline void recordColorLookup(const Texture& texture, const float* s, const float* t, const float* const* rgbaLanes) {
  SampleTrace* trace = tActiveSampleTrace;
  if (!trace) [[likely]] return;
  SampleRecord record;
  record.texture = &texture;
  record.s = s[trace->lane];
  record.t = t[trace->lane];
  for (int c = 0; c < 4; ++c) record.result[c] = rgbaLanes[c][trace->lane];
  explainColor(texture, record);
  trace->records.push_back(record);
}

inline void recordCompareLookup(const Texture& depth, const float* s, const float* t, const float* ref, const float* result) {
  SampleTrace* trace = tActiveSampleTrace;
  if (!trace) [[likely]] return;
  SampleRecord record;
  record.texture = &depth;
  record.compare = true;
  record.s = s[trace->lane];
  record.t = t[trace->lane];
  record.ref = ref[trace->lane];
  record.result[0] = result[trace->lane];
  explainCompare(depth, record);
  trace->records.push_back(record);
}

}  // namespace raster::sampling
