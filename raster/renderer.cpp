// Passes, draws and binning; rasterization of the binned tiles in parallel (renderer.h).
#include "raster/renderer.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "raster/texture/format.h"
#include "raster/geometry/clip.h"
#include "raster/tile/rasterize_tile.h"
#include "raster/util/cycles.h"

namespace raster {

PipelineCounters& PipelineCounters::operator+=(const PipelineCounters& o) {
  trianglesIn += o.trianglesIn;
  trianglesClipped += o.trianglesClipped;
  trianglesRejected += o.trianglesRejected;
  trianglesSetUp += o.trianglesSetUp;
  tileBinEntries += o.tileBinEntries;
  laneGroupsShaded += o.laneGroupsShaded;
  lanesShaded += o.lanesShaded;
  lanesCovered += o.lanesCovered;
  vertexCycles += o.vertexCycles;
  setupCycles += o.setupCycles;
  binCycles += o.binCycles;
  rasterCycles += o.rasterCycles;
  shadeCycles += o.shadeCycles;
  mergeCycles += o.mergeCycles;
  return *this;
}

Renderer::Renderer(int threads, bool scalarOnly) : pool_(threads), scalarOnly_(scalarOnly) {}

Renderer::~Renderer() = default;

void Renderer::beginPass(const Framebuffer& framebuffer, const Viewport& viewport, const ClearValues& clearValues) {
  flush();
  framebuffer_ = framebuffer;
  tilesX_ = (framebuffer.width + kTileSize - 1) / kTileSize;
  tilesY_ = (framebuffer.height + kTileSize - 1) / kTileSize;
  // Bins keep their capacity from pass to pass (flush empties them).
  if (bins_.size() != size_t(tilesX_) * size_t(tilesY_)) bins_.assign(size_t(tilesX_) * size_t(tilesY_), {});

  // GL viewport -> scale/translate (_mesa_get_viewport_xform), mirrored for window-system
  // buffers as st_atom_viewport does for Y_0_TOP framebuffers. Depth range [0, 1].
  const float halfWidth = 0.5f * float(viewport.width), halfHeight = 0.5f * float(viewport.height);
  viewport_.scale[0] = halfWidth;
  viewport_.translate[0] = halfWidth + float(viewport.x);
  viewport_.scale[1] = halfHeight;
  viewport_.translate[1] = halfHeight + float(viewport.y);
  viewport_.scale[2] = 0.5f;
  viewport_.translate[2] = 0.5f;
  if (framebuffer.flipY) {
    viewport_.scale[1] = -viewport_.scale[1];
    viewport_.translate[1] = float(framebuffer.height) - viewport_.translate[1];
  }
  pendingClear_ = clearValues;
}

// Clears one rectangle of the bound framebuffer: glClear, carried out tile by tile inside
// the tiles' tasks (parallel, and the tile's pixels are then in cache for its triangles).
void Renderer::clearRect(int x0, int y0, int x1, int y1, bool colorToo) const {
  const ClearValues& values = pendingClear_;
  const size_t width = size_t(framebuffer_.width);
  // Every row of the rectangle stored from 32 bytes of repeated texels held in registers:
  // a texel is 4, 8 or 16 bytes, so the pattern lines up at any texel. (Copying a first row
  // into the others cost a library call per 256-byte row and read as much as it wrote.)
  auto fillRows = [&](auto* data, const auto* texel, size_t perTexel) {
    if (x1 <= x0 || y1 <= y0) return;
    const size_t texelBytes = perTexel * sizeof(*texel);
    unsigned char pattern[32];
    for (size_t i = 0; i < sizeof pattern; i += texelBytes) std::memcpy(pattern + i, texel, texelBytes);
    const size_t rowBytes = size_t(x1 - x0) * texelBytes;
    for (int y = y0; y < y1; ++y) {
      unsigned char* row = reinterpret_cast<unsigned char*>(data + (size_t(y) * width + size_t(x0)) * perTexel);
      size_t i = 0;
      for (; i + sizeof pattern <= rowBytes; i += sizeof pattern) std::memcpy(row + i, pattern, sizeof pattern);
      std::memcpy(row + i, pattern, rowBytes - i);
    }
  };
  if (values.color && colorToo) {
    for (Texture* target : framebuffer_.colors) {
      if (target->format == TexelFormat::RGBA8) {
        uint8_t texel[4];
        for (int c = 0; c < 4; ++c) texel[c] = format::unorm8FromFloat(std::clamp(values.colorValue[c], 0.0f, 1.0f));
        fillRows(target->rgba8.data(), texel, 4);
      } else if (target->format == TexelFormat::RGBA32F) {
        fillRows(target->f32.data(), values.colorValue, 4);
      } else if (target->format == TexelFormat::RGBA16F) {
        uint16_t texel[4];
        for (int c = 0; c < 4; ++c) texel[c] = format::halfFromFloatTowardZero(values.colorValue[c]);
        fillRows(target->half.data(), texel, 4);
      }
    }
  }
  if (values.depth && framebuffer_.depth) {
    const uint32_t code = format::depthClearCode(values.depthValue, framebuffer_.depth->depthBits());
    fillRows(framebuffer_.depth->depth.data(), &code, 1);
  }
}

// Assembles primitives [first, end) of a draw (instance-major: every primitive of instance 0,
// then of instance 1, ...), clips those that need it and sets up the rest, appending them
// to `out` in that order.
void Renderer::assemble(const AssemblyInput& in, size_t first, size_t end, SetupOutput out) const {
  const size_t perInstance = in.indices.size() / 3;
  clip::Clipper clipper(in.setup.varyingFloats, viewport_);
  for (size_t p = first; p < end; ++p) {
    const int base = int(p / perInstance) * in.vertexCount;
    const size_t t = (p % perInstance) * 3;
    const int r0 = base + int(in.indices[t]), r1 = base + int(in.indices[t + 1]), r2 = base + int(in.indices[t + 2]);
    const unsigned m0 = in.shaded.clipMask[size_t(r0)], m1 = in.shaded.clipMask[size_t(r1)], m2 = in.shaded.clipMask[size_t(r2)];
    out.counters.trianglesIn++;
    if (m0 & m1 & m2) {   // all three outside one plane
      out.counters.trianglesRejected++;
      continue;
    }
    if ((m0 | m1 | m2) == 0) {
      out.counters.trianglesSetUp += setupTriangle(in.setup, in.shaded.record(r0), in.shaded.record(r1),
                                                   in.shaded.record(r2), in.drawIndex, out.triangles, out.varyingPlanes);
      continue;
    }
    out.counters.trianglesClipped++;
    const clip::Polygon& polygon =
        clipper.clipTriangle(in.shaded.record(r0), in.shaded.record(r1), in.shaded.record(r2), m0 | m1 | m2);
    for (int i = 2; i < polygon.count; ++i) {
      out.counters.trianglesSetUp += setupTriangle(in.setup, polygon.vertex[i - 1], polygon.vertex[i], polygon.vertex[0],
                                                   in.drawIndex, out.triangles, out.varyingPlanes);
    }
  }
}

// Appends the first `chunks` setup chunks to the pass's triangles, in chunk order; each
// chunk's varying-plane indices move by where its planes land.
void Renderer::appendChunks(int chunks) {
  size_t triangleCount = triangles_.size(), planeCount = varyingPlanes_.size();
  for (int c = 0; c < chunks; ++c) {
    SetupChunk& chunk = setupChunks_[size_t(c)];
    chunk.triangleAt = triangleCount;
    chunk.planeAt = planeCount;
    triangleCount += chunk.triangles.size();
    planeCount += chunk.varyingPlanes.size();
    counters_ += chunk.counters;
  }
  triangles_.resize(triangleCount);
  varyingPlanes_.resize(planeCount);
  pool_.parallelFor(chunks, [&](int c) {
    const SetupChunk& chunk = setupChunks_[size_t(c)];
    SetupTriangle* to = triangles_.data() + chunk.triangleAt;
    for (const SetupTriangle& tri : chunk.triangles) {
      *to = tri;
      to->varyingBase += uint32_t(chunk.planeAt);
      ++to;
    }
    std::copy(chunk.varyingPlanes.begin(), chunk.varyingPlanes.end(), varyingPlanes_.begin() + std::ptrdiff_t(chunk.planeAt));
  });
}

void Renderer::draw(std::unique_ptr<ShaderInstance> shader, const VertexStream& vertices,
                    std::span<const uint32_t> indices, const RasterState& state, int instanceCount) {
  if (framebuffer_.width <= 0) throw std::logic_error("Renderer::draw before beginPass");
  const int varyingFloats = shader->varyingFloats();
  // The vertex stage addresses the buffer with 32-bit float offsets (its gathers).
  if (size_t(vertices.vertexCount) * size_t(vertices.strideFloats) > size_t(std::numeric_limits<int32_t>::max()))
    throw std::length_error("vertex buffer of " + std::to_string(vertices.vertexCount) + " vertices is too large");
  for (uint32_t index : indices)
    if (index >= uint32_t(vertices.vertexCount))
      throw std::out_of_range("index " + std::to_string(index) + " past the vertex buffer (" +
                              std::to_string(vertices.vertexCount) + " vertices)");

  // Vertex shading: every vertex of the buffer once per instance; instances in parallel.
  const uint64_t vertexStart = cycleCount();
  ShadedVertices& shaded = shaded_;   // every record is written below, so old contents never show
  shaded.varyingFloats = varyingFloats;
  shaded.stride = vertex_stage::kVaryingOffset + varyingFloats;
  const size_t records = size_t(vertices.vertexCount) * size_t(instanceCount);
  // Grown, never shrunk: a resize back up after a small draw (a fullscreen pass between
  // two scenes) would zero the whole buffer again, which every record overwrites anyway.
  if (shaded.data.size() < records * size_t(shaded.stride)) shaded.data.resize(records * size_t(shaded.stride));
  shaded.clipMask.resize(records);
  pool_.parallelFor(instanceCount, [&](int instance) {
    shader->shadeVertices(vertices, instance, instance * vertices.vertexCount, viewport_, shaded);
  });

  const uint64_t setupStart = cycleCount();
  counters_.vertexCycles += setupStart - vertexStart;

  // Primitive assembly, clipping and setup, in API order.
  SetupState setup;
  setup.framebufferWidth = framebuffer_.width;
  setup.framebufferHeight = framebuffer_.height;
  setup.bottomEdgeRule = framebuffer_.flipY;
  setup.cullBack = state.cullBack;
  setup.polygonOffset = state.polygonOffset;
  setup.offsetFactor = state.offsetFactor;
  // With no depth buffer llvmpipe uses the 24-bit resolvable difference.
  setup.offsetUnitsScaled = polygonOffsetUnits(state.offsetUnits, framebuffer_.depth ? framebuffer_.depth->depthBits() : 24);
  setup.varyingFloats = varyingFloats;

  const uint32_t drawIndex = uint32_t(draws_.size());
  const uint32_t firstTriangle = uint32_t(triangles_.size());
  const AssemblyInput input{setup, shaded, indices, vertices.vertexCount, drawIndex};
  const size_t primitives = size_t(instanceCount) * (indices.size() / 3);
  // Large draws are set up in chunks of primitives in parallel, each into its own lists,
  // which are then appended in chunk order: the same triangles in the same order as one
  // pass through them, for any thread count.
  const int chunks = pool_.threads() > 1 && primitives >= 2 * kSetupChunkPrimitives
                         ? int(std::min<size_t>(primitives / kSetupChunkPrimitives, size_t(4 * pool_.threads())))
                         : 1;
  if (chunks == 1) {
    assemble(input, 0, primitives, {triangles_, varyingPlanes_, counters_});
  } else {
    if (setupChunks_.size() < size_t(chunks)) setupChunks_.resize(size_t(chunks));
    pool_.parallelFor(chunks, [&](int c) {
      SetupChunk& chunk = setupChunks_[size_t(c)];
      chunk.triangles.clear();
      chunk.varyingPlanes.clear();
      chunk.counters = {};
      assemble(input, primitives * size_t(c) / size_t(chunks), primitives * size_t(c + 1) / size_t(chunks),
               {chunk.triangles, chunk.varyingPlanes, chunk.counters});
    });
    appendChunks(chunks);
  }
  const bool samplesTextures = shader->samplesTextures();
  const int colorOutputs = shader->colorOutputs();
  draws_.push_back(RecordedDraw{std::move(shader), state, samplesTextures, varyingFloats, colorOutputs});
  const uint64_t binStart = cycleCount();
  counters_.setupCycles += binStart - setupStart;
  bin(firstTriangle);
  counters_.binCycles += cycleCount() - binStart;
}

// Bins triangles [firstTriangle, end) into the tiles their bounds touch, skipping tiles
// that one edge function rejects at all four corners of the overlap. Bands of tile rows
// are binned in parallel: each band's tiles get their triangles in order, whoever bins
// the other bands.
void Renderer::bin(uint32_t firstTriangle) {
  const size_t count = triangles_.size() - firstTriangle;
  const int bands = pool_.threads() > 1 && count >= kSetupChunkPrimitives ? std::min(tilesY_, 4 * pool_.threads()) : 1;
  std::atomic<uint64_t> entries{0};
  auto binBand = [&](int band) {
    uint64_t binned = 0;
    const int bandY0 = tilesY_ * band / bands, bandY1 = tilesY_ * (band + 1) / bands - 1;
    for (uint32_t t = firstTriangle; t < triangles_.size(); ++t) {
      const SetupTriangle& tri = triangles_[t];
      const int tileY0 = std::max(tri.minY / kTileSize, bandY0), tileY1 = std::min(tri.maxY / kTileSize, bandY1);
      for (int tileY = tileY0; tileY <= tileY1; ++tileY) {
        for (int tileX = tri.minX / kTileSize; tileX <= tri.maxX / kTileSize; ++tileX) {
          const int x0 = std::max(tileX * kTileSize, tri.minX), x1 = std::min(tileX * kTileSize + kTileSize - 1, tri.maxX);
          const int y0 = std::max(tileY * kTileSize, tri.minY), y1 = std::min(tileY * kTileSize + kTileSize - 1, tri.maxY);
          bool outside = false;
          for (const EdgeFunction& e : tri.edge)
            outside = outside || std::max({e.at(x0, y0), e.at(x1, y0), e.at(x0, y1), e.at(x1, y1)}) <= 0;
          if (outside) continue;
          bins_[size_t(tileY) * size_t(tilesX_) + size_t(tileX)].push_back(t);
          ++binned;
        }
      }
    }
    entries += binned;
  };
  if (bands == 1) binBand(0);
  else pool_.parallelFor(bands, binBand);
  counters_.tileBinEntries += entries;
}

// Worth it (and exact) when some colour draw is depth tested, and no colour draw blends:
// then the colour a pixel ends with is that of the last colour fragment to pass its test.
bool Renderer::visibilityFirst() const {
  if (!visibilityFirstAllowed_ || !framebuffer_.depth) return false;
  bool depthTested = false;
  for (const RecordedDraw& draw : draws_) {
    if (colorOutputsWritten(draw, framebuffer_) == 0) continue;
    if (draw.state.blendAdditive) return false;
    depthTested |= draw.state.depthTest;
  }
  return depthTested;
}

void Renderer::flush() {
  const bool clearing = pendingClear_.color || pendingClear_.depth;
  if (!triangles_.empty() || clearing) {
    TileJob job;
    job.framebuffer = &framebuffer_;
    job.triangles = triangles_;
    job.varyingPlanes = varyingPlanes_;
    job.draws = draws_;
    job.timeStages = timeStages_;
    job.visibilityFirst = visibilityFirst();
    std::vector<PipelineCounters> tileCounters(bins_.size());
    pool_.parallelFor(int(bins_.size()), [&](int tile) {
      const int tileX = tile % tilesX_, tileY = tile / tilesX_;
      if (clearing) {
        const int x0 = tileX * kTileSize, y0 = tileY * kTileSize;
        const int x1 = std::min(x0 + kTileSize, framebuffer_.width), y1 = std::min(y0 + kTileSize, framebuffer_.height);
        // A colour clear the tile's first triangle overwrites whole is skipped (same bytes).
        clearRect(x0, y0, x1, y1, !firstTriangleOverwritesColor(job, bins_[size_t(tile)], x0, y0, x1, y1));
      }
      if (bins_[size_t(tile)].empty()) return;
      if (scalarOnly_) rasterizeTile<ScalarLanes>(job, tileX, tileY, bins_[size_t(tile)], tileCounters[size_t(tile)]);
      else rasterizeTile<FastLanes>(job, tileX, tileY, bins_[size_t(tile)], tileCounters[size_t(tile)]);
    });
    for (const PipelineCounters& c : tileCounters) counters_ += c;
  }
  pendingClear_ = {};
  triangles_.clear();
  varyingPlanes_.clear();
  draws_.clear();
  for (auto& b : bins_) b.clear();
}

}  // namespace raster
