// Passes and draws: the stages in order, and the threads they run on (renderer.h).
#include "raster/renderer.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "raster/geometry/assemble.h"
#include "raster/merge/clear.h"
#include "raster/methods.h"
#include "raster/shading_rate.h"
#include "raster/simd/gl_math.h"
#include "raster/tile/coarse_tile.h"
#include "raster/tile/inspect_tile.h"
#include "raster/tile/rasterize_tile.h"
#include "raster/tile/tile_clear.h"
#include "raster/tile/trace_tile.h"
#include "raster/util/cache_size.h"
#include "raster/util/cycles.h"
#include "raster/util/hilbert.h"

namespace raster {

PipelineCounters& PipelineCounters::operator+=(const PipelineCounters& o) {
  trianglesIn += o.trianglesIn;
  trianglesClipped += o.trianglesClipped;
  trianglesRejected += o.trianglesRejected;
  trianglesSetUp += o.trianglesSetUp;
  tileBinEntries += o.tileBinEntries;
  depthRangeWalks += o.depthRangeWalks;
  texelPlaneTexels += o.texelPlaneTexels;
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
  pool_.wake();   // so the helper is running by the pass's first parallel loop (ThreadPool::wake)
  framebuffer_ = framebuffer;
  bins_.reset(framebuffer.width, framebuffer.height);

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
  if (history_) beginPassHistory();
}

// A new pass's record in the pixel history, probed when the history asks and the probe
// pixel lies inside the framebuffer.
void Renderer::beginPassHistory() {
  PassHistory pass;
  pass.pass = int(history_->passes.size());
  pass.colors.assign(framebuffer_.colors.begin(), framebuffer_.colors.end());
  pass.depth = framebuffer_.depth;
  pass.width = framebuffer_.width;
  pass.height = framebuffer_.height;
  pass.flipY = framebuffer_.flipY;
  pass.clear = pendingClear_;
  const auto probe = history_->probes.find(pass.pass);
  if (probe != history_->probes.end()) {
    const auto [x, y] = probe->second;
    pass.probed = x >= 0 && y >= 0 && x < framebuffer_.width && y < framebuffer_.height;
    pass.x = x;
    pass.y = y;
  }
  history_->passes.push_back(std::move(pass));
}

// Appends what the first `chunks` setup chunks spilled past their windows to the pass's
// lists, each chunk's after the last, its planes with it; sums the chunks' counters.
void Renderer::appendSpills(int chunks) {
  for (int c = 0; c < chunks; ++c) {
    SetupChunk& chunk = setupChunks_[size_t(c)];
    counters_ += chunk.counters;
    const SetupWindow& window = chunk.window;
    chunk.spillAt = triangles_.size();
    if (window.spill.empty()) continue;
    const uint32_t planeAt = uint32_t(varyingPlanes_.size());
    for (SetupTriangle tri : window.spill) {
      tri.varyingBase += planeAt;
      triangles_.push_back(tri);
    }
    varyingPlanes_.insert(varyingPlanes_.end(), window.spillPlanes.begin(), window.spillPlanes.end());
  }
}

void Renderer::draw(std::unique_ptr<ShaderInstance> shader, const VertexStream& vertices,
                    std::span<const uint32_t> indices, const RasterState& state, int instanceCount) {
  if (framebuffer_.width <= 0) throw std::logic_error("Renderer::draw before beginPass");
  // The vertex stage addresses the buffer with 32-bit float offsets (its gathers).
  if (size_t(vertices.vertexCount) * size_t(vertices.strideFloats) > limits::kMaxVertexBufferFloats)
    throw std::length_error("vertex buffer of " + std::to_string(vertices.vertexCount) + " vertices is too large");
  for (uint32_t index : indices)
    if (index >= uint32_t(vertices.vertexCount))
      throw std::out_of_range("index " + std::to_string(index) + " past the vertex buffer (" +
                              std::to_string(vertices.vertexCount) + " vertices)");

  // Values the fragments would make of single texels, made once a texel (shader/texel_planes.h).
  const uint64_t planesStart = cycleCount();
  counters_.texelPlaneTexels += shader->makeTexelPlanes(pool_, framebuffer_, scalarOnly_);
  counters_.shadeCycles += cycleCount() - planesStart;

  // 1. Fetch and vertex shading.
  const uint64_t vertexStart = cycleCount();
  shadeVertices(*shader, vertices, instanceCount);
  const uint64_t setupStart = cycleCount();
  counters_.vertexCycles += setupStart - vertexStart;

  // 2-3. Primitive assembly, clipping and setup, in API order.
  SetupState setup;
  setup.framebufferWidth = framebuffer_.width;
  setup.framebufferHeight = framebuffer_.height;
  setup.bottomEdgeRule = framebuffer_.flipY;
  setup.cullBack = state.cullBack;
  setup.polygonOffset = state.polygonOffset;
  setup.offsetFactor = state.offsetFactor;
  // With no depth buffer llvmpipe uses the 24-bit resolvable difference.
  setup.offsetUnitsScaled = polygonOffsetUnits(state.offsetUnits, framebuffer_.depth ? framebuffer_.depth->depthBits() : 24);
  setup.varyingFloats = shaded_.varyingFloats;
  setup.drawIndex = uint32_t(draws_.size());
  const uint32_t firstTriangle = uint32_t(triangles_.size());
  const int chunks = setUpChunked(setup, indices, vertices.vertexCount, size_t(instanceCount) * (indices.size() / 3));
  if (history_ && !history_->passes.empty()) history_->passes.back().programs.push_back(shader->name());
  const bool samplesTextures = shader->samplesTextures();
  const int colorOutputs = shader->colorOutputs();
  const bool lanesIndependent = shader->lanesIndependent();
  const bool samplesAroundPixel = shader->samplesAroundPixel();
  draws_.push_back(DrawRecord{std::move(shader), state, samplesTextures, setup.varyingFloats, colorOutputs,
                              uint32_t(indices.size() / 3), lanesIndependent, samplesAroundPixel});

  // 4. Binning.
  const uint64_t binStart = cycleCount();
  counters_.setupCycles += binStart - setupStart;
  bin(firstTriangle, chunks);
  counters_.binCycles += cycleCount() - binStart;
}

// Every vertex of the buffer once per instance, into shaded_: instances, and ranges of a
// large buffer's vertices, in parallel (each vertex is shaded on its own, so the records
// are the same however they are split).
// The vertex stage runs under its own view of the method set (math=fast-fragment keeps
// llvmpipe's math here); no fragment work is in flight while it runs, and the pool's
// hand-off orders the switch before the workers read it.
void Renderer::shadeVertices(const ShaderInstance& shader, const VertexStream& vertices, int instanceCount) {
  const ScopedMethods vertexMethods(vertexStageSet(methods::active()));
  ShadedVertices& shaded = shaded_;   // every record is written, so old contents never show
  shaded.varyingFloats = shader.varyingFloats();
  shaded.stride = vertex_record::kVaryings + shaded.varyingFloats;
  const size_t records = size_t(vertices.vertexCount) * size_t(instanceCount);
  // Grown, never shrunk: a resize back up after a small draw (a fullscreen pass between
  // two scenes) would zero the whole buffer again, which every record overwrites anyway.
  if (shaded.data.size() < records * size_t(shaded.stride)) shaded.data.resize(records * size_t(shaded.stride));
  shaded.clipMask.resize(records);
  // Fewer instances than items to share out: split each instance's vertices too.
  const int items = 4 * pool_.threads();
  const int ranges = pool_.threads() > 1 && instanceCount < items ? std::clamp(vertices.vertexCount / kVertexRange, 1, items) : 1;
  pool_.parallelFor(instanceCount * ranges, [&](int item) {
    const int instance = item / ranges, range = item % ranges;
    const VertexBatch batch{vertices, viewport_, instance, instance * vertices.vertexCount,
                            int(int64_t(vertices.vertexCount) * range / ranges),
                            int(int64_t(vertices.vertexCount) * (range + 1) / ranges)};
    shader.shadeVertices(batch, shaded, scalarOnly_);
  });
}

// Assembles and sets up a draw's primitives into the pass's lists. Large draws are set up
// in chunks of primitives in parallel, each into the window of the lists reserved for it, a
// slot per primitive (setup.h): the same triangles in the same order as one pass through
// them, for any thread count, with holes where primitives were culled, which no bin
// names. Pixel history and the stage views, which read the lists whole, take one chunk.
// Returns the number of chunks.
int Renderer::setUpChunked(const SetupState& setup, std::span<const uint32_t> indices, int vertexCount,
                           size_t primitives) {
  const AssemblyInput input{setup, shaded_, indices, vertexCount, viewport_, !scalarOnly_};
  const int chunks = pool_.threads() > 1 && primitives >= 2 * kSetupChunkPrimitives && !history_ && !viewRecorder_
                         ? int(std::min<size_t>(primitives / kSetupChunkPrimitives, size_t(4 * pool_.threads())))
                         : 1;
  if (chunks == 1) {
    assemblePrimitives(input, 0, primitives, {triangles_, varyingPlanes_, history_ ? &triangleOrigins_ : nullptr}, counters_);
    return 1;
  }
  if (setupChunks_.size() < size_t(chunks)) setupChunks_.resize(size_t(chunks));
  const size_t firstTriangle = triangles_.size(), firstPlane = varyingPlanes_.size();
  const size_t planesPerTriangle = size_t(setup.varyingFloats);
  triangles_.resize(firstTriangle + primitives);
  varyingPlanes_.resize(firstPlane + primitives * planesPerTriangle);
  const auto chunkStart = [&](int c) { return primitives * size_t(c) / size_t(chunks); };
  pool_.parallelFor(chunks, [&](int c) {
    SetupChunk& chunk = setupChunks_[size_t(c)];
    SetupWindow& window = chunk.window;
    window.first = window.next = firstTriangle + chunkStart(c);
    window.end = firstTriangle + chunkStart(c + 1);
    window.nextPlane = firstPlane + chunkStart(c) * planesPerTriangle;
    window.spilling = false;
    window.spill.clear();
    window.spillPlanes.clear();
    chunk.counters = {};
    assemblePrimitives(input, chunkStart(c), chunkStart(c + 1), {triangles_, varyingPlanes_, nullptr, &window},
                       chunk.counters);
  });
  appendSpills(chunks);
  return chunks;
}

// Bins the draw's triangles (geometry/bin.h): [firstTriangle, end), or with more than one
// setup chunk, each chunk's window, then what it spilled. Large draws are binned in parts,
// consecutive ranges of triangles (whole chunks) in parallel, each into its own bins;
// appending those in range order gives every tile its triangles in API order.
void Renderer::bin(uint32_t firstTriangle, int setupChunks) {
  uint32_t count = uint32_t(triangles_.size()) - firstTriangle;
  if (setupChunks > 1) {
    count = 0;
    for (int c = 0; c < setupChunks; ++c) count += uint32_t(setupChunks_[size_t(c)].window.written());
  }
  // A part per thread, of at least half a setup chunk's triangles (each part's own bins
  // cost a pass over every tile to empty and append), and whole chunks to each.
  const int parts = std::max(1, std::min({pool_.threads(), int(count / (kSetupChunkPrimitives / 2)),
                                          setupChunks > 1 ? setupChunks : pool_.threads()}));
  // Part p into `into`: the chunks [setupChunks * p / parts, setupChunks * (p + 1) / parts),
  // each its window's written slots, then its spill (API order); without chunks, an even
  // share of the triangles.
  const auto binPart = [&](TileBins& into, int p) {
    if (setupChunks == 1) {
      const auto start = [&](int q) { return firstTriangle + uint32_t(uint64_t(count) * uint32_t(q) / uint32_t(parts)); };
      return into.binTriangles(triangles_, start(p), start(p + 1));
    }
    uint64_t entries = 0;
    for (int c = setupChunks * p / parts; c < setupChunks * (p + 1) / parts; ++c) {
      const SetupChunk& chunk = setupChunks_[size_t(c)];
      entries += into.binTriangles(triangles_, uint32_t(chunk.window.first), uint32_t(chunk.window.next)) +
                 into.binTriangles(triangles_, uint32_t(chunk.spillAt), uint32_t(chunk.spillAt + chunk.window.spill.size()));
    }
    return entries;
  };
  if (parts == 1) {
    counters_.tileBinEntries += binPart(bins_, 0);
    return;
  }
  if (binParts_.size() < size_t(parts - 1)) binParts_.resize(size_t(parts - 1));
  std::vector<uint64_t> entries(static_cast<size_t>(parts));
  pool_.parallelFor(parts, [&](int p) {
    // The first part goes straight into the pass's bins: it follows what they hold.
    TileBins& part = p == 0 ? bins_ : binParts_[size_t(p - 1)];
    if (p > 0) part.reset(framebuffer_.width, framebuffer_.height);
    entries[size_t(p)] = binPart(part, p);
  });
  for (int p = 0; p < parts; ++p) {
    if (p > 0) bins_.append(binParts_[size_t(p - 1)]);
    counters_.tileBinEntries += entries[size_t(p)];
  }
}

// Worth it (and exact) when some colour draw is depth tested, and no colour draw blends:
// then the colour a pixel ends with is that of the last colour fragment to pass its test.
bool Renderer::visibilityFirst() const {
  if (!visibilityFirstAllowed_ || !framebuffer_.depth) return false;
  bool depthTested = false;
  for (const DrawRecord& draw : draws_) {
    if (colorOutputsWritten(draw, framebuffer_) == 0) continue;
    if (draw.state.blendAdditive) return false;
    depthTested |= draw.state.depthTest;
  }
  return depthTested;
}

// The pass's work items in Hilbert order of their tiles (raster::samplesAroundPixel), a
// tile's bands in the order of their first rows. The other passes keep rows of tiles: their
// reads and writes run on along a texel row from one tile into the next, which the hardware
// prefetchers and the row prefetches of lookups and stores (prefetchFootprintRows,
// merge::prefetchBlockRowsForWrite) count on. docs/notes/2026-11-30-hilbert-order-ssao.md
// has both orders' times.
void Renderer::orderAlongHilbertCurve() {
  const int tilesX = bins_.tilesX(), tilesY = bins_.tilesY();
  const uint32_t side = hilbertSide(uint32_t(std::max(tilesX, tilesY)));
  auto key = [&](const TileWorkItem& item) {
    const uint32_t x = uint32_t(item.tile % tilesX), y = uint32_t(item.tile / tilesX);
    return std::pair(hilbertIndex(x, y, side), item.bounds.y0);
  };
  std::sort(workItems_.begin(), workItems_.end(), [&](const TileWorkItem& a, const TileWorkItem& b) { return key(a) < key(b); });
}

// 5-6. Every tile of the pass (or band of one, or range of its triangles), in parallel: its
// share of the clear, then its triangles through tile/ and merge/.
void Renderer::flush() {
  const bool clearing = pendingClear_.color || pendingClear_.depth;
  if (!triangles_.empty() || clearing) {
    // llvmpipe's blend into a half-float target leaves its thread keeping denormals from the
    // first block whose fragments all fail the depth test on (simd/gl_math.h, the top). This
    // renderer keeps them from the first pass into a half-float target with a depth-tested
    // colour draw on: llvmpipe's mode for every later pass wherever that pass has such a block,
    // as each scene's has (overdraw). Where it has none (no triangle behind another) llvmpipe
    // flushes on; in that pass itself, it flushes in the blocks shaded before the first one.
    const auto halfFloat = [](const Texture* t) { return t->format == TexelFormat::RGBA16F; };   // RGB16F is stored so too
    const auto depthTestedColor = [&](const DrawRecord& draw) {
      return draw.state.depthTest && colorOutputsWritten(draw, framebuffer_) > 0;
    };
    if (!triangles_.empty() && framebuffer_.depth && std::any_of(draws_.begin(), draws_.end(), depthTestedColor) &&
        std::any_of(framebuffer_.colors.begin(), framebuffer_.colors.end(), halfFloat))
      fragmentsKeepDenormals_ = true;
    const glsl::ScopedDenormalMode denormals(!fragmentsKeepDenormals_);
    if (history_ && !history_->passes.empty()) history_->passes.back().keepsDenormals = fragmentsKeepDenormals_;
    TileJob job;
    job.framebuffer = &framebuffer_;
    job.triangles = triangles_;
    job.varyingPlanes = varyingPlanes_;
    job.draws = draws_;
    job.timeStages = timeStages_;
    job.visibilityFirst = visibilityFirst();
    std::tie(job.coarseWidth, job.coarseHeight) = passShadingRate(draws_, framebuffer_);
    for (size_t k = 0; k < framebuffer_.colors.size(); ++k)
      if (framebuffer_.colors[k]->format == TexelFormat::RGBA8) job.unorm8Outputs |= 1u << k;
    const bool coarse = job.coarseWidth > 1 || job.coarseHeight > 1;
    // Streaming stores skip the read for ownership but leave nothing in cache, and wait to
    // reach memory: targets that fit the threads' caches stay there until the next frame's
    // clear (docs/notes/2026-11-21-what-made-it-faster.md, "streaming clears only where
    // the targets outgrow the caches").
    const auto bytes = [](const Texture& t) { return textureStorageBytes(t.width, t.height, t.format); };
    uint64_t targetBytes = framebuffer_.depth ? bytes(*framebuffer_.depth) : 0;
    for (const Texture* target : framebuffer_.colors) targetBytes += bytes(*target);
    job.streamUntouchedClears = targetBytes > uint64_t(pool_.threads()) * privateCacheBytesPerCore();
    // A pass of few tiles (the small end of a bloom chain) would leave threads idle, or
    // waiting on the one large tile among small ones: its tiles of few triangles are cut
    // into bands of whole 16-row regions, each its own item with the tile's whole bin (the
    // walk skips triangles beside the band, walk.h; a tile of many triangles stays whole, as
    // each band would walk them all). Every pixel is owned by one band and none depends on
    // another, so the bytes are the same; stage views and pixel history time or trace whole
    // tiles, and keep them. docs/notes/2026-11-29-two-threads-wait.md has the passes' times
    // before and after.
    constexpr size_t kBandedTileMaxTriangles = 16;
    const int tiles = bins_.tileCount();
    const bool fewTiles = pool_.threads() > 1 && tiles < 8 * pool_.threads() && !viewRecorder_ && !history_;
    workItems_.clear();
    binSizes_.resize(size_t(tiles));
    for (int tile = 0; tile < tiles; ++tile) {
      binSizes_[size_t(tile)] = bins_.bin(tile).size();
      const TileBounds whole = bins_.bounds(tile);
      const bool banded = fewTiles && binSizes_[size_t(tile)] <= kBandedTileMaxTriangles;
      const int bandRows = banded ? limits::kRegionSize : limits::kTileSize;
      for (int y = whole.y0; y <= whole.y1; y += bandRows)
        workItems_.push_back({tile, TileBounds{whole.x0, y, whole.x1, std::min(y + bandRows - 1, whole.y1)}});
    }
    // A depth-only pass's heavy tiles walk their triangles in ranges on several threads, the
    // later ranges into copies of the depth target folded in after the loop (tile/depth_ranges.h).
    if (pool_.threads() > 1 && !coarse && !viewRecorder_ && !history_ && mayWalkDepthRanges(draws_, framebuffer_))
      if (const int ranges = cutHeavyTiles(workItems_, binSizes_, pool_.threads()); ranges > 1)
        depthCopies_.prepare(framebuffer_, ranges - 1);
    if (std::any_of(draws_.begin(), draws_.end(), [](const DrawRecord& d) { return d.samplesAroundPixel; }))
      orderAlongHilbertCurve();
    std::vector<PipelineCounters> itemCounters(workItems_.size());
    // A stage view records the pass; its fragment counts take the instrumented walk.
    ViewPass* view = viewRecorder_ ? &viewRecorder_->beginPass(job, bins_.tilesX(), bins_.tilesY()) : nullptr;
    if (view) {   // what decides the items without a recorder: bench/scaling_model.py models them from it
      std::copy(binSizes_.begin(), binSizes_.end(), view->tileTriangles.begin());
      view->depthRanges = !coarse && mayWalkDepthRanges(draws_, framebuffer_);
    }
    const bool inspect = view && viewRecorder_->what() == ViewRecorder::Record::Fragments;
    // Pixel history: the tile holding the pass's probe pixel is walked by trace_tile.h.
    PassHistory* traced = history_ && !history_->passes.empty() && history_->passes.back().probed
                              ? &history_->passes.back() : nullptr;
    const int tracedTile = traced ? (traced->y / limits::kTileSize) * bins_.tilesX() + traced->x / limits::kTileSize : -1;
    pool_.parallelFor(int(workItems_.size()), [&](int item) {
      const uint64_t viewStart = view ? cycleCount() : 0;
      const TileWorkItem& work = workItems_[size_t(item)];
      const int tile = work.tile;
      const TileBounds bounds = work.bounds;
      const std::span<const uint32_t> bin = work.triangles(bins_.bin(tile));
      if (work.range > 0) {   // a later range: into its copy, no clear
        TileJob rangeJob = job;
        rangeJob.framebuffer = &depthCopies_.beginRange(work.range - 1, bounds);
        if (scalarOnly_) rasterizeTile<ScalarLanes>(rangeJob, bounds, bin, itemCounters[size_t(item)]);
        else rasterizeTile<FastLanes>(rangeJob, bounds, bin, itemCounters[size_t(item)]);
        ++itemCounters[size_t(item)].depthRangeWalks;
        return;
      }
      // A coarse-rate pass: the whole clear, then the coarse walk (tile/coarse_tile.h), or
      // its traced (trace_tile.h) or counted (inspect_tile.h) copy, which leave its bytes.
      if (coarse) {
        if (clearing) merge::clearRect(framebuffer_, pendingClear_, bounds, true, bin.empty() && job.streamUntouchedClears);
        if (tile == tracedTile && (clearing || traced->fragments.empty()))
          traced->afterClear = readPixel(framebuffer_, traced->x, traced->y);
        if (tile == tracedTile)
          traceTileCoarse(job, bounds, bin, uint32_t(traced->programs.size() - draws_.size()), triangleOrigins_, *traced,
                          itemCounters[size_t(item)]);
        else if (inspect) inspectTileCoarse(job, bounds, bin, view->counts, itemCounters[size_t(item)]);
        else if (scalarOnly_) rasterizeTileCoarse<ScalarLanes>(job, bounds, bin, itemCounters[size_t(item)]);
        else rasterizeTileCoarse<FastLanes>(job, bounds, bin, itemCounters[size_t(item)]);
        if (view) view->tileCycles[size_t(tile)] = cycleCount() - viewStart;
        return;
      }
      if (tile == tracedTile) {
        if (clearing) merge::clearRect(framebuffer_, pendingClear_, bounds, true);
        if (clearing || traced->fragments.empty()) traced->afterClear = readPixel(framebuffer_, traced->x, traced->y);
        // Draws of this job are counted from 0; the pass's list already holds all of them.
        const uint32_t drawBase = uint32_t(traced->programs.size() - draws_.size());
        traceTile(job, bounds, bin, drawBase, triangleOrigins_, *traced, itemCounters[size_t(item)]);
        return;
      }
      // Clears the tile's first triangle overwrites are left out (tile/tile_clear.h); a
      // depth-only first triangle may have done its own work in place of the depth clear.
      // The instrumented walk of a stage view counts every fragment: a whole clear, then
      // the whole bin.
      size_t done = 0;
      if (clearing && inspect) merge::clearRect(framebuffer_, pendingClear_, bounds, true);
      else if (clearing)
        done = scalarOnly_ ? clearTile<ScalarLanes>(job, bin, bounds, pendingClear_, itemCounters[size_t(item)])
                           : clearTile<FastLanes>(job, bin, bounds, pendingClear_, itemCounters[size_t(item)]);
      if (bin.size() > done) {
        if (inspect) inspectTile(job, bounds, bin, view->counts, itemCounters[size_t(item)]);
        else if (scalarOnly_) rasterizeTile<ScalarLanes>(job, bounds, bin.subspan(done), itemCounters[size_t(item)]);
        else rasterizeTile<FastLanes>(job, bounds, bin.subspan(done), itemCounters[size_t(item)]);
      }
      if (view) view->tileCycles[size_t(tile)] = cycleCount() - viewStart;
    });
    for (const TileWorkItem& work : workItems_)
      if (work.range > 0) depthCopies_.fold(work.range - 1, framebuffer_, work.bounds);
    // Which tiles of the colour targets still hold only the clear: those no triangle reached.
    std::vector<uint8_t> touched(size_t(bins_.tileCount()));
    for (int tile = 0; tile < bins_.tileCount(); ++tile) touched[size_t(tile)] = !bins_.bin(tile).empty();
    merge::recordClearedTiles(framebuffer_, pendingClear_.color, bins_.tilesX(), touched);
    PipelineCounters passCounters;
    for (const PipelineCounters& c : itemCounters) passCounters += c;
    counters_ += passCounters;
    if (view) viewRecorder_->endPass(passCounters);
    if (traced) traced->stored = readPixel(framebuffer_, traced->x, traced->y);
  }
  pendingClear_ = {};
  triangles_.clear();
  varyingPlanes_.clear();
  triangleOrigins_.clear();
  draws_.clear();
  bins_.clear();
}

}  // namespace raster
