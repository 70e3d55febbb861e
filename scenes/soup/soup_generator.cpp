// The soup generator (soup.h): per seed, triangles of every kind and a few closed meshes.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "scenes/soup/soup.h"

namespace scenes::soup {
namespace {

// Distributions written out, so the same seed gives the same numbers with any standard
// library (std::uniform_*_distribution are implementation-defined).
class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}
  uint64_t bits() { return engine_(); }
  double unit() { return double(bits() >> 11) * 0x1p-53; }                 // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }   // [lo, hi)
  int below(int n) { return int(bits() % uint64_t(n)); }                     // 0 .. n-1
  int range(int lo, int hi) { return lo + below(hi - lo + 1); }              // lo .. hi
  bool chance(int percent) { return below(100) < percent; }
  double sign() { return chance(50) ? 1.0 : -1.0; }
  // 2^k for k in lo..hi, times [1, 2): a size spread evenly over orders of magnitude.
  double magnitude(int lo, int hi) {
    const double mantissa = 1.0 + unit();
    return std::ldexp(mantissa, range(lo, hi));
  }

 private:
  std::mt19937_64 engine_;
};

// log2 of the viewport's larger side, rounded up: the largest on-screen size class.
int sizeBits(int width, int height) {
  int bits = 0;
  while ((1 << bits) < std::max(width, height)) ++bits;
  return bits;
}

class Generator {
 public:
  Generator(uint64_t seed, int width, int height) : rng_(seed), width_(width), height_(height) {}

  Triangle triangle() {
    // Weights per kind: the ones that find bugs in coverage and clipping get most.
    static constexpr struct { Kind kind; int weight; } kWeights[] = {
        {Kind::General, 12},   {Kind::Tiny, 10},      {Kind::Sliver, 10},    {Kind::PixelGrid, 12},
        {Kind::FarOut, 9},     {Kind::Huge, 8},       {Kind::NearZeroW, 8},  {Kind::NegativeW, 8},
        {Kind::DepthPlanes, 7}, {Kind::Degenerate, 8}, {Kind::NonFinite, 4},
    };
    int total = 0;
    for (const auto& entry : kWeights) total += entry.weight;
    int pick = rng_.below(total);
    Kind kind = Kind::General;
    for (const auto& entry : kWeights) {
      if (pick < entry.weight) {
        kind = entry.kind;
        break;
      }
      pick -= entry.weight;
    }
    Triangle t;
    t.kind = kind;
    switch (kind) {
      case Kind::General: general(t); break;
      case Kind::Tiny: tiny(t); break;
      case Kind::Sliver: sliver(t); break;
      case Kind::PixelGrid: pixelGrid(t); break;
      case Kind::FarOut: farOut(t); break;
      case Kind::Huge: huge(t); break;
      case Kind::NearZeroW: nearZeroW(t); break;
      case Kind::NegativeW: negativeW(t); break;
      case Kind::DepthPlanes: depthPlanes(t); break;
      case Kind::Degenerate: degenerate(t); break;
      case Kind::NonFinite: nonFiniteTriangle(t); break;
    }
    return t;
  }

  ClosedMesh fan() {
    ClosedMesh m;
    m.kind = MeshKind::Fan;
    const glm::dvec2 centre = onScreen();
    double radius = rng_.magnitude(0, sizeBits(width_, height_));
    m.note = "on screen";
    switch (rng_.below(4)) {
      case 0: radius = rng_.magnitude(10, 20); m.note = "rim far off screen"; break;
      case 1: radius = rng_.magnitude(-3, 1); m.note = "a few pixels"; break;
      default: break;
    }
    const double aspect = rng_.uniform(0.25, 1.0);   // an ellipse, either way round
    const glm::dvec2 axes = rng_.chance(50) ? glm::dvec2(radius, radius * aspect) : glm::dvec2(radius * aspect, radius);
    const bool flatW = rng_.chance(30);
    auto vertex = [&](glm::dvec2 window) {
      const double z = rng_.uniform(-0.9, 0.9);
      return toClip(window, z, flatW ? 1.0 : rng_.uniform(0.5, 4.0));
    };
    m.clip.push_back(vertex(centre));
    // Rim points in angle order, evenly spread and jittered by up to 0.4 of their spacing:
    // with 5 or more, no gap reaches half a turn, so the centre stays inside the outline.
    const int rim = rng_.range(5, 32);
    for (int i = 0; i < rim; ++i) {
      const double turn = (i + 0.5 + rng_.uniform(-0.4, 0.4)) / rim;   // [0, 1) of a turn
      m.clip.push_back(vertex(centre + axes * circlePoint(turn)));
      m.outline.push_back(uint32_t(i + 1));
    }
    for (int i = 0; i < rim; ++i) m.indices.insert(m.indices.end(), {0u, uint32_t(i + 1), uint32_t((i + 1) % rim + 1)});
    return m;
  }

  ClosedMesh strip() {
    ClosedMesh m;
    m.kind = MeshKind::Strip;
    const int columns = rng_.range(1, 12), rows = rng_.range(1, 12);
    const int cellBits = std::max(0, sizeBits(width_, height_) - 3);
    glm::dvec2 cell{rng_.magnitude(-1, cellBits), rng_.magnitude(-1, cellBits)};
    glm::dvec2 corner = onScreen() - 0.5 * cell * glm::dvec2(columns, rows);
    m.note = "on screen";
    switch (rng_.below(5)) {
      case 0:
        cell = glm::dvec2{rng_.magnitude(-5, -2), rng_.magnitude(-5, -2)};
        m.note = "sub-pixel cells";
        break;
      case 1:
        cell = glm::dvec2{rng_.magnitude(8, 18), rng_.magnitude(8, 18)};
        corner = onScreen();   // the viewport point lies in cell (k, l) of the grid
        corner -= cell * glm::dvec2{double(rng_.range(1, columns)), double(rng_.range(1, rows))};
        corner += cell * glm::dvec2{rng_.unit(), rng_.unit()};
        m.note = "far off screen";
        break;
      default: break;
    }
    const bool flatW = rng_.chance(30);
    // Interior vertices move by up to 0.2 of a cell each way and edge vertices along their
    // edge only: every quad stays convex (a move of 1/4 could flatten a corner), so both
    // triangles of a quad keep their orientation and the rectangle is tiled exactly once.
    for (int row = 0; row <= rows; ++row) {
      for (int column = 0; column <= columns; ++column) {
        glm::dvec2 jitter{rng_.uniform(-0.2, 0.2), rng_.uniform(-0.2, 0.2)};
        if (column == 0 || column == columns) jitter.x = 0.0;
        if (row == 0 || row == rows) jitter.y = 0.0;
        const glm::dvec2 window = corner + cell * (glm::dvec2(column, row) + jitter);
        const double z = rng_.uniform(-0.9, 0.9);
        m.clip.push_back(toClip(window, z, flatW ? 1.0 : rng_.uniform(0.5, 4.0)));
      }
    }
    const auto at = [&](int column, int row) { return uint32_t(row * (columns + 1) + column); };
    for (int row = 0; row < rows; ++row) {
      for (int column = 0; column < columns; ++column) {
        const uint32_t a = at(column, row), b = at(column + 1, row), c = at(column, row + 1), d = at(column + 1, row + 1);
        // The triangles a GL strip along the row makes; odd rows take the other diagonal.
        if (row % 2 == 0) m.indices.insert(m.indices.end(), {a, b, c, c, b, d});
        else m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
      }
    }
    m.outline = {at(0, 0), at(columns, 0), at(columns, rows), at(0, rows)};
    return m;
  }

 private:
  Rng rng_;
  int width_, height_;

  // Clip coordinates of a window position (GL, y up) at NDC depth z with this w.
  glm::vec4 toClip(glm::dvec2 window, double ndcZ, double w) const {
    const double ndcX = window.x * 2.0 / width_ - 1.0, ndcY = window.y * 2.0 / height_ - 1.0;
    return {float(ndcX * w), float(ndcY * w), float(ndcZ * w), float(w)};
  }
  // Every helper draws its numbers in a fixed order: one draw per statement, or inside a
  // braced list (sequenced left to right), never two among a call's arguments or an
  // operator's operands, whose order C++ leaves to the compiler.
  glm::dvec2 onScreen() { return glm::dvec2{rng_.uniform(0.0, width_), rng_.uniform(0.0, height_)}; }
  double perspectiveW() { return rng_.uniform(0.5, 4.0); }
  double depth() { return rng_.uniform(-0.99, 0.99); }
  glm::dvec2 around(glm::dvec2 centre, double size) {
    return centre + glm::dvec2{rng_.uniform(-size, size), rng_.uniform(-size, size)};
  }
  void fromWindow(Triangle& t, const glm::dvec2 (&p)[3]) {
    for (int v = 0; v < 3; ++v) {
      const double z = depth();
      t.clip[v] = toClip(p[v], z, perspectiveW());
    }
  }

  // A point of the unit circle `turn` of the way round, with + - * / only: a quarter of the
  // circle from the rational parametrization ((1 - u^2), 2u) / (1 + u^2), u in [0, 1), then
  // turned by whole quarters (exact).
  static glm::dvec2 circlePoint(double turn) {
    const double quarters = turn * 4.0;
    const int quarter = std::min(3, int(quarters));
    const double u = quarters - quarter;
    const glm::dvec2 p((1.0 - u * u) / (1.0 + u * u), 2.0 * u / (1.0 + u * u));
    switch (quarter) {
      case 0: return p;
      case 1: return {-p.y, p.x};
      case 2: return {-p.x, -p.y};
      default: return {p.y, -p.x};
    }
  }

  void general(Triangle& t) {
    const glm::dvec2 c = onScreen();
    const double size = rng_.magnitude(-1, sizeBits(width_, height_));
    fromWindow(t, {around(c, size), around(c, size), around(c, size)});
  }

  void tiny(Triangle& t) {
    glm::dvec2 c = onScreen();
    const double size = std::ldexp(1.0, -rng_.range(0, 10));
    if (rng_.chance(50)) c = glm::floor(c) + 0.5 - 0.5 * size;   // straddling a pixel centre
    glm::dvec2 p[3];
    for (glm::dvec2& q : p) q = c + size * glm::dvec2{rng_.unit(), rng_.unit()};
    fromWindow(t, p);
  }

  void sliver(Triangle& t) {
    const glm::dvec2 c = onScreen();
    const glm::dvec2 far = around(c, rng_.magnitude(0, sizeBits(width_, height_)));
    if (rng_.chance(50)) {   // two vertices nearly coincident
      const double gap = rng_.chance(20) ? 0.0 : std::ldexp(1.0, -rng_.range(0, 12));
      fromWindow(t, {c, c + gap * glm::dvec2{rng_.uniform(-1, 1), rng_.uniform(-1, 1)}, far});
    } else {                 // the third vertex just off the middle of a long edge
      const glm::dvec2 mid = 0.5 * (c + far);
      const double off = std::ldexp(1.0, -rng_.range(2, 20));
      fromWindow(t, {c, far, mid + off * glm::dvec2{rng_.uniform(-1, 1), rng_.uniform(-1, 1)}});
    }
  }

  // Window coordinates on the half-pixel grid (pixel edges k, pixel centres k + 0.5), with
  // w a power of two: the clip coordinates are exact for power-of-two viewports.
  void pixelGrid(Triangle& t) {
    auto gridX = [&] { return 0.5 * rng_.range(-2, 2 * width_ + 2); };
    auto gridY = [&] { return 0.5 * rng_.range(-2, 2 * height_ + 2); };
    glm::dvec2 p[3];
    p[0] = glm::dvec2{gridX(), gridY()};
    if (rng_.chance(50)) {   // a right triangle whose legs lie on grid lines
      const int span = std::max(2, std::min(width_, height_));
      p[1] = p[0] + glm::dvec2(0.5 * rng_.range(-span, span), 0.0);
      p[2] = p[0] + glm::dvec2(0.0, 0.5 * rng_.range(-span, span));
    } else {
      p[1] = glm::dvec2{gridX(), gridY()};
      p[2] = glm::dvec2{gridX(), gridY()};
    }
    for (int v = 0; v < 3; ++v) {
      const double z = depth();
      t.clip[v] = toClip(p[v], z, std::ldexp(1.0, rng_.range(-2, 2)));
    }
  }

  void farOut(Triangle& t) {
    auto far = [&] {
      const glm::dvec2 c(0.5 * width_, 0.5 * height_);
      const double signX = rng_.sign(), x = rng_.magnitude(10, 24), signY = rng_.sign(), y = rng_.magnitude(10, 24);
      return c + glm::dvec2(signX * x, signY * y);
    };
    if (rng_.chance(25)) {   // a huge triangle around the whole viewport
      const double f = rng_.magnitude(10, 24);
      fromWindow(t, {{-f, -f}, {3 * f, -f}, {-f, 3 * f}});
      return;
    }
    glm::dvec2 p[3] = {onScreen(), onScreen(), onScreen()};
    const int outside = rng_.range(1, 3);
    for (int v = 0; v < outside; ++v) p[v] = far();
    fromWindow(t, p);
  }

  void huge(Triangle& t) {
    general(t);
    if (rng_.chance(60)) {   // the same picture with every coordinate scaled up to ~1e30
      const double sign = rng_.sign();
      const float scale = float(sign * std::ldexp(1.0, rng_.range(20, 99)));
      for (glm::vec4& v : t.clip) v *= scale;
    } else {                 // one coordinate of one vertex between 1e20 and 1e30, w = 1
      glm::vec4& v = t.clip[rng_.below(3)];
      v /= v.w;
      const int axis = rng_.below(3);
      const double sign = rng_.sign();
      v[axis] = float(sign * rng_.uniform(1e20, 1e30));
    }
  }

  void nearZeroW(Triangle& t) {
    general(t);
    glm::vec4& v = t.clip[rng_.below(3)];
    const double sign = rng_.sign(), mantissa = 1.0 + rng_.unit();
    const double w = sign * std::ldexp(mantissa, -rng_.range(10, 126));
    const double zScale = rng_.chance(50) ? std::fabs(w) : 1.0;   // inside the depth range, or not
    v = glm::vec4{float(rng_.uniform(-1, 1)), float(rng_.uniform(-1, 1)), float(rng_.uniform(-1, 1) * zScale), float(w)};
  }

  void negativeW(Triangle& t) {
    general(t);
    const int behind = rng_.range(1, 3);
    for (int i = 0; i < behind; ++i) {
      glm::vec4& v = t.clip[i];
      if (rng_.chance(50)) v = -v;   // the mirror image through the eye
      else v = glm::vec4{float(rng_.uniform(-2, 2)), float(rng_.uniform(-2, 2)), float(rng_.uniform(-2, 2)),
                         float(-rng_.uniform(0.25, 4.0))};
    }
  }

  void depthPlanes(Triangle& t) {
    general(t);
    for (glm::vec4& v : t.clip) {
      switch (rng_.below(3)) {
        case 0: v.z = float(rng_.sign()) * v.w; break;                  // exactly on a plane
        case 1: v.z = float(rng_.uniform(-1.5, 1.5) * v.w); break;      // either side of it
        default: break;
      }
    }
  }

  void degenerate(Triangle& t) {
    pixelGrid(t);
    switch (rng_.below(3)) {
      case 0: t.clip[1] = t.clip[2] = t.clip[0]; break;   // a point
      case 1: t.clip[2] = t.clip[rng_.below(2)]; break;   // a repeated vertex: a line
      default: {                                          // collinear, at a shared w
        const glm::vec4 a = t.clip[0] / t.clip[0].w, b = t.clip[1] / t.clip[1].w;
        const float s[] = {0.5f, 2.0f, -1.0f};
        const glm::vec4 c = a + s[rng_.below(3)] * (b - a);
        t.clip[0] = a;
        t.clip[1] = b;
        t.clip[2] = c;
      }
    }
  }

  void nonFiniteTriangle(Triangle& t) {
    general(t);
    const float values[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity()};
    const int count = rng_.range(1, 2);
    for (int i = 0; i < count; ++i) {
      const int vertex = rng_.below(3), component = rng_.below(4);
      t.clip[vertex][component] = values[rng_.below(3)];
    }
  }
};

constexpr const char* kKindNames[] = {"general",    "tiny",       "sliver",       "pixel-grid",
                                      "far-out",    "huge",       "near-zero-w",  "negative-w",
                                      "depth-planes", "degenerate", "non-finite"};

}  // namespace

const char* kindName(Kind kind) { return kKindNames[int(kind)]; }

Kind kindFromName(const std::string& name) {
  for (int i = 0; i < int(std::size(kKindNames)); ++i)
    if (name == kKindNames[i]) return Kind(i);
  throw std::invalid_argument("unknown triangle kind '" + name + "'");
}

const char* meshKindName(MeshKind kind) { return kind == MeshKind::Fan ? "fan" : "strip"; }

MeshKind meshKindFromName(const std::string& name) {
  if (name == "fan") return MeshKind::Fan;
  if (name == "strip") return MeshKind::Strip;
  throw std::invalid_argument("unknown closed-mesh kind '" + name + "' (fan or strip)");
}

Soup generate(uint64_t seed, int width, int height, int triangles) {
  if (width < 1 || height < 1 || triangles < 0 || uint32_t(triangles) > kMaxTriangles)
    throw std::invalid_argument("soup: bad size or triangle count");
  Generator generator(seed, width, height);
  Soup soup;
  soup.seed = seed;
  soup.width = width;
  soup.height = height;
  for (int i = 0; i < triangles; ++i) soup.triangles.push_back(generator.triangle());
  soup.meshes.push_back(generator.fan());
  soup.meshes.push_back(generator.strip());
  return soup;
}

bool nonFinite(const Triangle& triangle) {
  for (const glm::vec4& v : triangle.clip)
    for (int c = 0; c < 4; ++c)
      if (!std::isfinite(v[c])) return true;
  return false;
}

glm::vec4 idColor(uint32_t id) {
  return {float(id & 0xFF) / 255.0f, float((id >> 8) & 0xFF) / 255.0f, float((id >> 16) & 0xFF) / 255.0f, 1.0f};
}

}  // namespace scenes::soup
