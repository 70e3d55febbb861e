// Pixel history's tile walk (trace_tile.h): the in-order walk of rasterize_tile.cpp with
// ScalarLanes, looking at the probe pixel on the way; and the coarse walk's (coarse_walk.h).
#include "raster/tile/trace_tile.h"

#include "raster/merge/color_write.h"
#include "raster/shader/shader_instance.h"
#include "raster/tile/coarse_shader.h"
#include "raster/tile/coarse_walk.h"
#include "raster/tile/depth_test.h"
#include "raster/tile/interpolate.h"
#include "raster/tile/walk.h"

namespace raster {
namespace {

using F = ScalarLanes;

// The lane of group `at` whose pixel is (x, y), or -1.
int laneAt(const LaneLayout<F>& layout, GroupAt at, int x, int y) {
  for (int i = 0; i < F::kCount; ++i)
    if (at.x + layout.dx[i] == x && at.y + layout.dy[i] == y) return i;
  return -1;
}

bool insideTriangle(const SetupTriangle& tri, int x, int y) {
  return x >= tri.minX && x <= tri.maxX && y >= tri.minY && y <= tri.maxY && tri.edge[0].at(x, y) > 0 &&
         tri.edge[1].at(x, y) > 0 && tri.edge[2].at(x, y) > 0;
}

// The weights of the triangle's vertices at pixel (x, y) from its edge functions: edge i
// runs from vertex i to vertex i + 1, so its value is the (scaled) area opposite vertex i + 2.
// Setup swapped vertices 0 and 1 of triangles clockwise in memory rows (setup.cpp); they are
// swapped back, so the weights follow the primitive's own vertex order.
void barycentrics(const SetupTriangle& tri, bool flipY, int x, int y, double out[3]) {
  double edge[3], sum = 0;
  for (int i = 0; i < 3; ++i) sum += edge[i] = double(tri.edge[i].at(x, y));
  for (int k = 0; k < 3; ++k) out[k] = sum != 0 ? edge[(k + 1) % 3] / sum : 0.0;
  const bool swapped = flipY ? !tri.frontFacing : tri.frontFacing;
  if (swapped) std::swap(out[0], out[1]);
}

uint32_t depthCodeOf(float z, const Texture& depth) {
  uint32_t codes[F::kCount];
  depthCodes(clampDepth(F(z)), depth.format, codes);
  return codes[0];
}

void recordInputs(const FragmentGroup<F>& group, int lane, int varyingFloats, FragmentRecord& record) {
  const glsl::vec4<F>& coord = group.in.gl_FragCoord;
  record.fragCoord[0] = coord.x[lane];
  record.fragCoord[1] = coord.y[lane];
  record.fragCoord[2] = coord.z[lane];
  record.fragCoord[3] = coord.w[lane];
  for (int v = 0; v < varyingFloats; ++v) record.varyings.push_back(group.varyings[v][lane]);
}

void recordOutputs(const FragmentOutput<F>& out, int lane, int outputs, FragmentRecord& record) {
  for (int k = 0; k < outputs; ++k)
    record.outputs.push_back({out.color[k].x[lane], out.color[k].y[lane], out.color[k].z[lane], out.color[k].w[lane]});
}


// The rest of a fragment's record, once its walk is done: which triangle it came from, its
// depth code, weights and the pixel after it; then it joins the pass's history.
void finishRecord(const TileJob& job, uint32_t index, uint32_t drawBase, std::span<const uint32_t> origins,
                  PassHistory& history, FragmentRecord& record) {
  const Framebuffer& fb = *job.framebuffer;
  const SetupTriangle& tri = job.triangles[index];
  const DrawRecord& draw = job.draws[tri.drawIndex];
  if (fb.depth) record.depthCode = depthCodeOf(record.z, *fb.depth);
  record.draw = drawBase + tri.drawIndex;
  const uint32_t perInstance = draw.primitivesPerInstance ? draw.primitivesPerInstance : 1;
  const uint32_t origin = index < origins.size() ? origins[index] : 0;
  const uint32_t primitive = origin & ~kClippedOrigin;
  record.instance = primitive / perInstance;
  record.primitive = primitive % perInstance;
  record.clipped = (origin & kClippedOrigin) != 0;
  record.frontFacing = tri.frontFacing;
  barycentrics(tri, fb.flipY, history.x, history.y, record.barycentric);
  record.after = readPixel(fb, history.x, history.y);
  history.fragments.push_back(std::move(record));
}

// The coarse walk's shader (coarse_walk.h's Shader) for the traced tile: every group is
// shaded at once as CoarseShader<ScalarLanes> does it, and the one holding the probe's
// coarse pixel is recorded on the way.
class TracingCoarseShader {
 public:
  TracingCoarseShader(const TileJob& job, const CoarseLayout<F>& coarse, PipelineCounters& counters, int x, int y,
                      FragmentRecord& record)
      : job_(job), coarse_(coarse), counters_(counters), record_(record) {
    const Framebuffer& fb = *job.framebuffer;
    coarseX_ = x - x % coarse.width;   // coarse pixels are aligned to the memory origin
    coarseY_ = y - y % coarse.height;
    coarseTexel_ = size_t(coarseY_) * size_t(fb.width) + size_t(coarseX_);
    pixel_ = (y - coarseY_) * coarse.width + (x - coarseX_);
  }
  CoarseGroup<F>& next() { return slot_; }
  void push() {
    FragmentGroup<F>& group = slot_.group;
    int lane = -1;
    for (int i = 0; i < F::kCount; ++i)
      if (group.texel[i] == coarseTexel_) lane = i;
    if (lane < 0) {
      shadeCoarseGroup(job_, coarse_, slot_, counters_);
      return;
    }
    const DrawRecord& draw = *group.draw;
    interpolateGroup(job_, group);
    FragmentRecord& record = record_;
    record.shaded = true;
    record.written = (slot_.laneMask[pixel_] >> lane & 1u) != 0;
    record.helper = !record.written;   // as at 1x1: shaded, but not written here
    record.lane = lane;
    record.coarseX = coarseX_;
    record.coarseY = coarseY_;
    for (int s = 0; s < coarse_.pixels; ++s)
      if (slot_.laneMask[s] >> lane & 1u) record.broadcast.push_back({coarseX_ + coarse_.pixelX[s], coarseY_ + coarse_.pixelY[s]});
    recordInputs(group, lane, draw.varyingFloats, record);
    sampling::SampleTrace samples;
    samples.lane = lane;
    sampling::tActiveSampleTrace = &samples;
    FragmentOutput<F> out;
    draw.shader->shadeFragments(group.in, group.varyings, out);
    sampling::tActiveSampleTrace = nullptr;
    counters_.laneGroupsShaded += 1;
    counters_.lanesShaded += F::kCount;
    recordOutputs(out, lane, draw.colorOutputs, record);
    record.samples = std::move(samples.records);
    writeCoarseGroup(job_, coarse_, slot_, out);
  }
  void flush() {}

 private:
  const TileJob& job_;
  const CoarseLayout<F>& coarse_;
  PipelineCounters& counters_;
  FragmentRecord& record_;
  int coarseX_ = 0, coarseY_ = 0, pixel_ = 0;
  size_t coarseTexel_ = 0;
  CoarseGroup<F> slot_;
};

}  // namespace

void traceTile(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, uint32_t drawBase,
               std::span<const uint32_t> origins, PassHistory& history, PipelineCounters& counters) {
  const Framebuffer& fb = *job.framebuffer;
  const LaneLayout<F> layout(fb.flipY, fb.width);
  const int px = history.x, py = history.y;
  for (uint32_t index : bin) {
    const SetupTriangle& tri = job.triangles[index];
    const DrawRecord& draw = job.draws[tri.drawIndex];
    const bool writesColor = colorOutputsWritten(draw, fb) > 0;
    FragmentRecord record;
    record.before = readPixel(fb, px, py);
    record.depthTested = draw.state.depthTest && fb.depth;
    bool seen = false;   // a lane group holding the probe pixel was walked

    // rasterize_tile.cpp's in-order walk (depthTestBin: ScalarLanes tests depth in quads).
    walkTriangle<F>(job, tri, layout, tile, [&](GroupAt at) {
      F z;
      const unsigned passed = depthTestGroup(job, tri, layout, at, z);
      const int lane = laneAt(layout, at, px, py);
      if (lane >= 0) {
        seen = true;
        record.covered = (at.laneMask >> lane & 1u) != 0;
        record.depthPassed = (passed >> lane & 1u) != 0;
        record.z = z[lane];
      }
      if (!passed || !writesColor) return;
      counters.lanesCovered += unsigned(__builtin_popcount(passed));
      FragmentGroup<F> group;
      fillGroup(job, tri, layout, GroupAt{at.x, at.y, passed}, z, group);
      sampling::SampleTrace samples;
      if (lane >= 0) {
        record.shaded = true;
        record.written = (passed >> lane & 1u) != 0;
        record.helper = !record.written;
        recordInputs(group, lane, draw.varyingFloats, record);
        samples.lane = lane;
        sampling::tActiveSampleTrace = &samples;
      }
      FragmentOutput<F> out;
      draw.shader->shadeFragments(group.in, group.varyings, out);
      sampling::tActiveSampleTrace = nullptr;
      counters.laneGroupsShaded += 1;
      counters.lanesShaded += F::kCount;
      if (lane >= 0) {
        recordOutputs(out, lane, draw.colorOutputs, record);
        record.samples = std::move(samples.records);
      }
      merge::writeGroup(fb, group, out);
    });

    // A depth-only draw tests the 16x16 regions wholly inside it along rows
    // (depthOnlyRegion), so no lane group held the pixel: the same arithmetic, recomputed.
    if (!seen && insideTriangle(tri, px, py) && !writesColor && record.depthTested) {
      seen = record.covered = record.regionFill = true;
      record.z = fragmentDepth(tri, F(float(px)), F(float(py)))[0];
      const uint32_t code = depthCodeOf(record.z, *fb.depth);
      const uint32_t stored = record.before.depthCode;
      record.depthPassed = draw.state.depthFunc == DepthFunc::Lequal ? code <= stored : code < stored;
    }
    if (!record.covered && !record.shaded) continue;   // the probe's quad, but not the probe
    finishRecord(job, index, drawBase, origins, history, record);
  }
}

void traceTileCoarse(const TileJob& job, const TileBounds& tile, std::span<const uint32_t> bin, uint32_t drawBase,
                     std::span<const uint32_t> origins, PassHistory& history, PipelineCounters& counters) {
  const Framebuffer& fb = *job.framebuffer;
  const LaneLayout<F> layout(fb.flipY, fb.width);
  const CoarseLayout<F> coarse(layout, job.coarseWidth, job.coarseHeight, fb.width);
  const int px = history.x, py = history.y;
  // rasterizeTileCoarse's loop (coarse_tile.cpp), triangle by triangle, through the same steps.
  for (size_t i = 0; i < bin.size(); ++i) {
    const uint32_t index = bin[i];
    const SetupTriangle& tri = job.triangles[index];
    const DrawRecord& draw = job.draws[tri.drawIndex];
    FragmentRecord record;
    record.before = readPixel(fb, px, py);
    record.depthTested = draw.state.depthTest && fb.depth;
    record.coarseWidth = coarse.width;
    record.coarseHeight = coarse.height;
    record.coarseX = px - px % coarse.width;   // aligned to the memory origin (coarse_tile.h)
    record.coarseY = py - py % coarse.height;
    record.covered = insideTriangle(tri, px, py);
    record.z = fragmentDepth(tri, F(float(px)), F(float(py)))[0];   // coverage and depth stay per pixel
    if (colorOutputsWritten(draw, fb) == 0) {   // depth only: the 1x1 walk's test and writes
      depthTestBin<F>(job, tile, bin.subspan(i, 1), layout, [](uint32_t, const SetupTriangle&, GroupAt, F) {});
      if (!record.covered) continue;
      if (record.depthTested) {
        const uint32_t code = depthCodeOf(record.z, *fb.depth), stored = record.before.depthCode;
        record.depthPassed = draw.state.depthFunc == DepthFunc::Lequal ? code <= stored : code < stored;
      }
      finishRecord(job, index, drawBase, origins, history, record);
      continue;
    }
    coarse_walk::PassedPixels passed;
    coarse_walk::passedPixels(job, tile, bin.subspan(i, 1), layout, passed, counters);
    if (record.covered && record.depthTested) record.depthPassed = passed.at(px - tile.x0, py - tile.y0);
    TracingCoarseShader shader(job, coarse, counters, px, py, record);
    coarse_walk::prepareCoarseGroups(job, tri, tile, coarse, passed, shader);
    if (!record.covered && !record.shaded) continue;   // neither the probe nor its coarse pixel
    finishRecord(job, index, drawBase, origins, history, record);
  }
}

}  // namespace raster
