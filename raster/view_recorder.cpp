// The stage views' pass records (view_recorder.h).
#include "raster/view_recorder.h"

#include <cmath>
#include <string>

#include "raster/shader/shader_instance.h"


namespace raster {
namespace {

// Where edges a and b of a set-up triangle cross, in pixels of memory rows. An edge is
// c - dcdx * x + dcdy * y = 0 with (x, y) measured from pixel (0, 0)'s centre, so the
// corners come back from the edge functions alone and setup keeps no vertices for the
// views. The fill rule's bias (at most one sub-pixel unit in c) moves a corner by less
// than 1/256 of a pixel. False for parallel edges (setup culls such triangles).
bool edgeCrossing(const EdgeFunction& a, const EdgeFunction& b, float& x, float& y) {
  const double det = double(a.dcdy) * double(b.dcdx) - double(a.dcdx) * double(b.dcdy);
  if (det == 0.0) return false;
  // -dcdx_a x + dcdy_a y = -c_a and the same for b, by Cramer's rule.
  const double cx = (double(a.dcdy) * double(b.c) - double(a.c) * double(b.dcdy)) / det;
  const double cy = (double(a.dcdx) * double(b.c) - double(a.c) * double(b.dcdx)) / det;
  if (!std::isfinite(cx) || !std::isfinite(cy)) return false;
  x = float(cx + 0.5);   // from pixel centres to pixel corners
  y = float(cy + 0.5);
  return true;
}

}  // namespace

ViewPass& ViewRecorder::beginPass(const TileJob& job, int tilesX, int tilesY) {
  const Framebuffer& fb = *job.framebuffer;
  if (reserve_) {
    const uint64_t pixels = uint64_t(fb.width) * uint64_t(fb.height);
    const uint64_t bytes = uint64_t(tilesX) * uint64_t(tilesY) * (sizeof(uint64_t) + sizeof(uint32_t)) +
                           (what_ == Record::Fragments ? pixels * FragmentCounts::kCountersPerPixel * sizeof(uint32_t) : 0) +
                           (what_ == Record::Triangles ? job.triangles.size() * sizeof(ViewTriangle) : 0);
    std::string what = "the view's record of pass ";
    for (const std::string& part : {std::to_string(passes_.size()), std::string(" ("), std::to_string(fb.width),
                                    std::string("x"), std::to_string(fb.height), std::string(")")})
      what.append(part);
    reserve_(bytes, what);
  }
  ViewPass& pass = passes_.emplace_back();
  pass.index = int(passes_.size()) - 1;
  pass.width = fb.width;
  pass.height = fb.height;
  pass.window = fb.flipY;
  pass.colorTargets = int(fb.colors.size());
  pass.depth = fb.depth != nullptr;
  pass.label = std::move(pendingLabel_);
  pendingLabel_.clear();
  for (const DrawRecord& draw : job.draws) pass.drawPrograms.push_back(draw.shader ? draw.shader->name() : "");
  pass.triangles = job.triangles.size();
  pass.tilesX = tilesX;
  pass.tilesY = tilesY;
  pass.tileCycles.assign(size_t(tilesX) * size_t(tilesY), 0);
  pass.tileTriangles.assign(size_t(tilesX) * size_t(tilesY), 0);
  if (what_ == Record::Fragments) pass.counts.reset(fb.width, fb.height);
  if (what_ == Record::Triangles) {
    pass.triangleList.reserve(job.triangles.size());
    for (const SetupTriangle& tri : job.triangles) {
      ViewTriangle corners{{}, {}, tri.drawIndex};
      bool ok = true;
      for (int e = 0; e < 3 && ok; ++e) ok = edgeCrossing(tri.edge[e], tri.edge[(e + 1) % 3], corners.x[e], corners.y[e]);
      if (ok) pass.triangleList.push_back(corners);
    }
  }
  return pass;
}

void ViewRecorder::endPass(const PipelineCounters& tileCounters) {
  if (!passes_.empty()) passes_.back().counters = tileCounters;
}

}  // namespace raster
