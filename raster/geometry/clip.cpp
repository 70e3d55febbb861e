// Homogeneous triangle clipping, ported from Mesa draw_pipe_clip.c (see clip.h).
#include "raster/geometry/clip.h"

#include <cmath>
#include <utility>

namespace raster::clip {
namespace {

using vertex_record::kClip;
using vertex_record::kVaryings;
using vertex_record::kWindow;





// draw_context.c: the six view-volume planes, in clip-mask bit order.
constexpr float kPlanes[6][4] = {
    {-1, 0, 0, 1}, {1, 0, 0, 1}, {0, -1, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {0, 0, -1, 1},
};

// draw_pipe_clip.c dot4: left to right, in float.
float planeDistance(const float* record, int plane) {
  const float* p = record + kClip;
  const float* n = kPlanes[plane];
  return p[0] * n[0] + p[1] * n[1] + p[2] * n[2] + p[3] * n[3];
}

bool isInfOrNan(float x) { return !std::isfinite(x); }

}  // namespace

Clipper::Clipper(int varyingFloats, const ViewportTransform& viewport)
    : stride_(kVaryings + varyingFloats), viewport_(viewport) {
  scratch_.resize(size_t(limits::kMaxClippedVertices + 1) * size_t(stride_));
}

// draw_pipe_clip.c interp(): LINTERP(t, out, in) = out + t * (in - out) on every float.
const float* Clipper::interpolate(float t, const float* out, const float* in) {
  float* dst = scratch_.data() + size_t(scratchUsed_++) * size_t(stride_);
  for (int c = 0; c < 4; ++c) dst[kClip + c] = out[kClip + c] + t * (in[kClip + c] - out[kClip + c]);
  const float* pos = dst + kClip;
  const float oow = 1.0f / pos[3];
  for (int c = 0; c < 3; ++c) dst[kWindow + c] = pos[c] * oow * viewport_.scale[c] + viewport_.translate[c];
  dst[kWindow + 3] = oow;
  for (int v = kVaryings; v < stride_; ++v) dst[v] = out[v] + t * (in[v] - out[v]);
  return dst;
}

const Polygon& Clipper::clipTriangle(const float* v0, const float* v1, const float* v2, unsigned mask) {
  scratchUsed_ = 0;
  Polygon* in = &polygons_[0];
  Polygon* out = &polygons_[1];
  in->count = 3;
  in->vertex[0] = v0;
  in->vertex[1] = v1;
  in->vertex[2] = v2;

  while (mask && in->count >= 3) {
    const int plane = __builtin_ctz(mask);
    mask &= ~(1u << plane);
    out->count = 0;

    const float* prev = in->vertex[0];
    float dpPrev = planeDistance(prev, plane);
    if (isInfOrNan(dpPrev)) { in->count = 0; break; }
    in->vertex[in->count] = in->vertex[0];   // close the loop without rotating vertices

    for (int i = 1; i <= in->count; ++i) {
      const float* vert = in->vertex[i];
      const float dp = planeDistance(vert, plane);
      if (isInfOrNan(dp)) { out->count = 0; in->count = 0; break; }

      bool differentSign;
      if (dpPrev >= 0.0f) {
        out->vertex[out->count++] = prev;
        differentSign = dp < 0.0f;
      } else {
        differentSign = !(dp < 0.0f);
      }

      if (differentSign) {
        const float denom = dp - dpPrev;
        const float* made;
        if (dp < 0.0f) {
          // Going out: interpolate from the vertex that is inside.
          made = (-dp < dpPrev) ? interpolate(dp / denom, vert, prev) : interpolate(-dpPrev / denom, prev, vert);
        } else {
          // Coming back in.
          made = (-dpPrev < dp) ? interpolate(-dpPrev / denom, prev, vert) : interpolate(dp / denom, vert, prev);
        }
        out->vertex[out->count++] = made;
      }
      prev = vert;
      dpPrev = dp;
    }
    std::swap(in, out);
  }
  return *in;
}

}  // namespace raster::clip
