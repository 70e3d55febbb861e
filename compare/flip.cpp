// ꟻLIP (LDR) error map (flip.h): a port of NVlabs/flip's src/cpp/FLIP.h (BSD-3-Clause,
// commit 1eb247c; "FLIP.h:N" below is a line of that file). The paper is Andersson et al.,
// "FLIP: A Difference Evaluator for Alternating Images", HPG 2020 (section numbers "§N").
//
// The pipeline, per pixel of both images:
//   1. sRGB bytes -> [0,1] -> linear RGB, clamped (the FLIP tool's loader and evaluate());
//   2. linear RGB -> XYZ -> YCxCz, the opponent space of the CSF filters (§4.1);
//   3. the spatial contrast-sensitivity filters, a sum of Gaussians per channel at the
//      viewer's pixels per degree, applied separably (§4.1, misc/separatedConvolutions.pdf);
//   4. back to linear RGB clamped to the cube, then CIELAB with the Hunt adjustment, and the
//      HyAB distance between the two images, raised to qc and redistributed with pc, pt into
//      [0, 1] (§4.2);
//   5. edge and point detectors (1st and 2nd derivatives of a Gaussian) on the unfiltered
//      luminance of each image, their differences raised to qf (§4.3);
//   6. error = colour difference ^ (1 - feature difference) (§4.4).
// Every float operation is the reference's, in the reference's order per pixel (no FMA: the
// project builds with -ffp-contract=off), so the map is the reference's bit for bit with the
// same C library (checked: tests/compare/fixtures/flip/README.md). The filters run taps
// outside and pixels inside, and bands of rows on several threads: neither changes a pixel's
// operations.
#include "compare/flip.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

namespace compare {
namespace {

// FLIP.h:101, and the float(PI * PI) its Gaussians use (FLIP.h:584).
constexpr float kPi = 3.14159265358979f;
constexpr float kPiSquared = kPi * kPi;

// The paper's constants (FLIP.h:125-133; §4): qc, the colour difference's exponent; pc and
// pt, the knee of the redistribution (differences up to pc * cmax map to [0, pt]); w, the
// feature detectors' width in degrees; qf, the feature difference's exponent.
constexpr float kQc = 0.7f;
constexpr float kPc = 0.4f;
constexpr float kPt = 0.95f;
constexpr float kW = 0.082f;
constexpr float kQf = 0.5f;

// The CSF's Gaussians per channel (FLIP.h:567-574; the paper's table 1): the achromatic and
// red-green channels are one Gaussian each (a1, b1), blue-yellow the sum of two (a1, b1 and
// a2, b2). Index 0 = Y, 1 = Cx, 2 = Cz.
constexpr float kA1[3] = {1.0f, 1.0f, 34.1f};
constexpr float kB1[3] = {0.0047f, 0.0053f, 0.04f};
constexpr float kA2[3] = {0.0f, 0.0f, 13.5f};
constexpr float kB2[3] = {1.0e-5f, 1.0e-5f, 0.025f};

// D65 white and its inverse (FLIP.h:106-107).
constexpr float kIlluminant[3] = {0.950428545f, 1.000000000f, 1.088900371f};
constexpr float kInvIlluminant[3] = {1.052156925f, 1.000000000f, 0.918357670f};

struct Color {
  float x, y, z;
};

// FLIP.h:330-337.
float sRGBToLinear(float sC) {
  if (sC <= 0.04045f) return sC / 12.92f;
  return powf((sC + 0.055f) / 1.055f, 2.4f);
}

// FLIP.h:367-386 (D65 sRGB primaries).
Color linearRGBToXYZ(Color rgb) {
  const float a11 = 10135552.0f / 24577794.0f, a12 = 8788810.0f / 24577794.0f, a13 = 4435075.0f / 24577794.0f;
  const float a21 = 2613072.0f / 12288897.0f, a22 = 8788810.0f / 12288897.0f, a23 = 887015.0f / 12288897.0f;
  const float a31 = 1425312.0f / 73733382.0f, a32 = 8788810.0f / 73733382.0f, a33 = 70074185.0f / 73733382.0f;
  return {a11 * rgb.x + a12 * rgb.y + a13 * rgb.z,
          a21 * rgb.x + a22 * rgb.y + a23 * rgb.z,
          a31 * rgb.x + a32 * rgb.y + a33 * rgb.z};
}

// FLIP.h:388-406.
Color xyzToLinearRGB(Color xyz) {
  const float a11 = 3.241003275f, a12 = -1.537398934f, a13 = -0.498615861f;
  const float a21 = -0.969224334f, a22 = 1.875930071f, a23 = 0.041554224f;
  const float a31 = 0.055639423f, a32 = -0.204011202f, a33 = 1.057148933f;
  return {a11 * xyz.x + a12 * xyz.y + a13 * xyz.z,
          a21 * xyz.x + a22 * xyz.y + a23 * xyz.z,
          a31 * xyz.x + a32 * xyz.y + a33 * xyz.z};
}

// FLIP.h:408-425.
Color xyzToCIELab(Color xyz) {
  const float delta = 6.0f / 29.0f;
  const float deltaSquare = delta * delta;
  const float deltaCube = delta * deltaSquare;
  const float factor = 1.0f / (3.0f * deltaSquare);
  const float term = 4.0f / 29.0f;
  float x = xyz.x * kInvIlluminant[0], y = xyz.y * kInvIlluminant[1], z = xyz.z * kInvIlluminant[2];
  x = x > deltaCube ? powf(x, 1.0f / 3.0f) : factor * x + term;
  y = y > deltaCube ? powf(y, 1.0f / 3.0f) : factor * y + term;
  z = z > deltaCube ? powf(z, 1.0f / 3.0f) : factor * z + term;
  return {116.0f * y - 16.0f, 500.0f * (x - y), 200.0f * (y - z)};
}

// FLIP.h:443-451: CIELAB's formulas without the cube root, linear in XYZ, so the CSF can
// be applied in it (§4.1).
Color xyzToYCxCz(Color xyz) {
  const float x = xyz.x * kInvIlluminant[0], y = xyz.y * kInvIlluminant[1], z = xyz.z * kInvIlluminant[2];
  return {116.0f * y - 16.0f, 500.0f * (x - y), 200.0f * (y - z)};
}

// FLIP.h:453-462.
Color yCxCzToXYZ(Color c) {
  const float y = (c.x + 16.0f) / 116.0f;
  const float cx = c.y / 500.0f;
  const float cz = c.z / 200.0f;
  const float x = y + cx;
  const float z = y - cz;
  return {x * kIlluminant[0], y * kIlluminant[1], z * kIlluminant[2]};
}

// FLIP.h:320-323 with its Max/Min macros (FLIP.h:103-104), so -0 clamps to +0 as there.
float clamp01(float v) {
  const float atLeast0 = v > 0.0f ? v : 0.0f;
  return atLeast0 > 1.0f ? 1.0f : atLeast0;
}

// The Hunt effect: chroma scaled with lightness (FLIP.h:470-473; §4.2).
float hunt(float luminance, float chrominance) { return 0.01f * luminance * chrominance; }

// HyAB: city-block in L, Euclidean in (a, b) (FLIP.h:475-480; §4.2).
float hyAB(Color a, Color b) {
  const float l = std::fabs(a.x - b.x);
  const float ab = std::sqrt((a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
  return l + ab;
}

// CIELAB with the Hunt adjustment applied to a and b.
Color huntLab(Color linearRGB) {
  const Color lab = xyzToCIELab(linearRGBToXYZ(linearRGB));
  return {lab.x, hunt(lab.x, lab.y), hunt(lab.x, lab.z)};
}

// cmax: the largest HyAB distance in the RGB cube, green against blue, raised to qc
// (FLIP.h:482-489; §4.2).
float maxColorDistance() {
  return powf(hyAB(huntLab({0.0f, 1.0f, 0.0f}), huntLab({0.0f, 0.0f, 1.0f})), kQc);
}

// A Gaussian in the paper's form a * sqrt(pi / b) * exp(-pi^2 x^2 / b) (FLIP.h:581-586), and
// its square-root-amplitude variant that lets the sum of two Gaussians be separated
// (FLIP.h:590-595; misc/separatedConvolutions.pdf).
float gaussianCsf(float x2, float a, float b) { return a * std::sqrt(kPi / b) * std::exp(-kPiSquared * x2 / b); }
float gaussianCsfSqrt(float x2, float a, float b) {
  return std::sqrt(a * std::sqrt(kPi / b)) * std::exp(-kPiSquared * x2 / b);
}

// The CSF filters reach three standard deviations of the widest Gaussian (FLIP.h:612-620).
int spatialFilterRadius(float ppd) {
  const float maxScale = std::max(std::max(std::max(kB1[0], kB1[1]), std::max(kB1[2], kB2[0])), std::max(kB2[1], kB2[2]));
  return int(std::ceil(3.0f * std::sqrt(maxScale / (2.0f * kPiSquared)) * ppd));
}

// The separable CSF filters (FLIP.h:1741-1776): Y and Cx one normalised Gaussian each; Cz
// two square-root Gaussians, normalised together, whose two separable passes are summed
// after the second pass.
struct SpatialFilters {
  std::vector<float> y, cx, cz1, cz2;
};

SpatialFilters spatialFilters(float ppd, int radius) {
  const float deltaX = 1.0f / ppd;
  const int width = 2 * radius + 1;
  SpatialFilters f{std::vector<float>(width), std::vector<float>(width), std::vector<float>(width),
                   std::vector<float>(width)};
  float sumY = 0.0f, sumCx = 0.0f, sumCz1 = 0.0f, sumCz2 = 0.0f;
  for (int x = 0; x < width; ++x) {
    const float ix = (x - radius) * deltaX;
    const float ix2 = ix * ix;
    f.y[x] = gaussianCsf(ix2, kA1[0], kB1[0]);
    f.cx[x] = gaussianCsf(ix2, kA1[1], kB1[1]);
    f.cz1[x] = gaussianCsfSqrt(ix2, kA1[2], kB1[2]);
    f.cz2[x] = gaussianCsfSqrt(ix2, kA2[2], kB2[2]);
    sumY += f.y[x];
    sumCx += f.cx[x];
    sumCz1 += f.cz1[x];
    sumCz2 += f.cz2[x];
  }
  const float normY = 1.0f / sumY, normCx = 1.0f / sumCx;
  const float normCz = 1.0f / std::sqrt(sumCz1 * sumCz1 + sumCz2 * sumCz2);
  for (int x = 0; x < width; ++x) {
    f.y[x] = f.y[x] * normY;
    f.cx[x] = f.cx[x] * normCx;
    f.cz1[x] = f.cz1[x] * normCz;
    f.cz2[x] = f.cz2[x] * normCz;
  }
  return f;
}

// The feature detectors (FLIP.h:1780-1825; §4.3): a Gaussian of standard deviation w/2
// degrees and its first and second derivatives, each derivative's positive and negative
// weights normalised to sum to +1 and -1.
struct FeatureFilter {
  std::vector<float> g, dg, ddg;
};

int featureFilterRadius(float ppd) { return int(std::ceil(3.0f * (0.5f * kW * ppd))); }   // FLIP.h:2256-2257

FeatureFilter featureFilter(float ppd) {
  const float stdDev = 0.5f * kW * ppd;
  const int radius = int(std::ceil(3.0f * stdDev));
  const int width = 2 * radius + 1;
  FeatureFilter f{std::vector<float>(width), std::vector<float>(width), std::vector<float>(width)};
  float gSum = 0.0f, dgSumNegative = 0.0f, dgSumPositive = 0.0f, ddgSumNegative = 0.0f, ddgSumPositive = 0.0f;
  for (int x = 0; x < width; ++x) {
    const int xx = x - radius;
    const float g = std::exp(-(float(xx) * float(xx)) / (2.0f * stdDev * stdDev));   // FLIP.h:576-579
    gSum += g;
    const float dg = -float(xx) * g;
    if (dg > 0.0f) dgSumPositive += dg;
    else dgSumNegative -= dg;
    const float ddg = (float(xx) * float(xx) / (stdDev * stdDev) - 1.0f) * g;
    if (ddg > 0.0f) ddgSumPositive += ddg;
    else ddgSumNegative -= ddg;
    f.g[x] = g;
    f.dg[x] = dg;
    f.ddg[x] = ddg;
  }
  for (int x = 0; x < width; ++x) {
    f.g[x] = f.g[x] / gSum;
    f.dg[x] = f.dg[x] / (f.dg[x] > 0.0f ? dgSumPositive : dgSumNegative);
    f.ddg[x] = f.ddg[x] / (f.ddg[x] > 0.0f ? ddgSumPositive : ddgSumNegative);
  }
  return f;
}

// An image in YCxCz, one plane per channel.
struct Planes {
  std::vector<float> y, cx, cz;
};

// Steps 1-2: bytes -> linear RGB (a table: the function of a byte, computed as the FLIP
// tool's loader does, FLIP-tool's imagehelpers.h ldrLoad then FLIP.h:349-356), clamped as
// evaluate() does (FLIP.h:2400), then YCxCz (FLIP.h:1335-1347).
Planes toYCxCz(const std::vector<uint8_t>& rgba8, size_t pixels) {
  float linear[256];
  for (int v = 0; v < 256; ++v) linear[v] = clamp01(sRGBToLinear(v / 255.0f));
  Planes p{std::vector<float>(pixels), std::vector<float>(pixels), std::vector<float>(pixels)};
  for (size_t i = 0; i < pixels; ++i) {
    const Color rgb{linear[rgba8[4 * i]], linear[rgba8[4 * i + 1]], linear[rgba8[4 * i + 2]]};
    const Color c = xyzToYCxCz(linearRGBToXYZ(rgb));
    p.y[i] = c.x;
    p.cx[i] = c.y;
    p.cz[i] = c.z;
  }
  return p;
}

// Runs fn(firstRow, endRow) over bands of rows on up to `threads` threads. Every pixel of
// the map is computed from the inputs alone, never from another pixel's result, so the split
// changes nothing in the output: the same bytes at any thread count.
template <typename Fn>
void forRowBands(int h, int threads, const Fn& fn) {
  const int bands = std::max(1, std::min(threads, h / 8));
  if (bands == 1) {
    fn(0, h);
    return;
  }
  std::vector<std::thread> workers;
  for (int b = 1; b < bands; ++b) workers.emplace_back(fn, int(int64_t(h) * b / bands), int(int64_t(h) * (b + 1) / bands));
  fn(0, int(int64_t(h) / bands));
  for (std::thread& t : workers) t.join();
}

// One row through a 1D filter along x, edge pixels repeated: out[x] = sum over k of
// f[k] * in[clamp(x + k - r)], added from k = 0 up as the reference's per-pixel loops do
// (FLIP.h:1861-1872, 1978-1996), so each pixel's sum is the same float operations in the same
// order; only the loops are swapped (taps outside, pixels inside) so neighbouring pixels run
// side by side in vector registers.
void filterRowX(const float* in, int w, const std::vector<float>& f, int r, std::vector<float>& padded, float* out) {
  padded.resize(size_t(w) + 2 * size_t(r));
  for (int i = 0; i < w + 2 * r; ++i) padded[size_t(i)] = in[std::min(std::max(0, i - r), w - 1)];
  std::fill(out, out + w, 0.0f);
  for (int k = 0; k <= 2 * r; ++k) {
    const float weight = f[size_t(k)];
    const float* src = padded.data() + k;
    for (int x = 0; x < w; ++x) out[x] += weight * src[x];
  }
}

// Row y of a plane through a 1D filter along y, edge rows repeated (FLIP.h:1892-1908,
// 2012-2029), in the same order per pixel as filterRowX.
void filterRowY(const std::vector<float>& plane, int w, int h, int y, const std::vector<float>& f, int r, float* out) {
  std::fill(out, out + w, 0.0f);
  for (int k = 0; k <= 2 * r; ++k) {
    const float weight = f[size_t(k)];
    const float* src = plane.data() + size_t(std::min(std::max(0, y + k - r), h - 1)) * size_t(w);
    for (int x = 0; x < w; ++x) out[x] += weight * src[x];
  }
}

// Steps 3-4 (FLIP.h:1830-1940): the colour difference of each pixel, in [0, 1].
std::vector<float> colorDifference(const Planes& ref, const Planes& test, int w, int h, float ppd, int threads) {
  const float cmax = maxColorDistance();
  const float pccmax = kPc * cmax;
  const int radius = spatialFilterRadius(ppd);
  const SpatialFilters f = spatialFilters(ppd, radius);
  const size_t pixels = size_t(w) * size_t(h);

  // Horizontal pass (FLIP.h:1850-1880). Per image: Y, Cx, and the blue-yellow channel
  // through both of its Gaussians.
  struct Pass {
    std::vector<float> y, cx, cz1, cz2;
  };
  Pass hr{std::vector<float>(pixels), std::vector<float>(pixels), std::vector<float>(pixels), std::vector<float>(pixels)};
  Pass ht = hr;
  forRowBands(h, threads, [&](int y0, int y1) {
    std::vector<float> padded;
    for (int y = y0; y < y1; ++y) {
      const size_t row = size_t(y) * size_t(w);
      for (auto [in, out] : {std::pair{&ref, &hr}, std::pair{&test, &ht}}) {
        filterRowX(in->y.data() + row, w, f.y, radius, padded, out->y.data() + row);
        filterRowX(in->cx.data() + row, w, f.cx, radius, padded, out->cx.data() + row);
        filterRowX(in->cz.data() + row, w, f.cz1, radius, padded, out->cz1.data() + row);
        filterRowX(in->cz.data() + row, w, f.cz2, radius, padded, out->cz2.data() + row);
      }
    }
  });

  // Vertical pass, then the filtered colour back into the RGB cube (clamped: the filters can
  // leave it), CIELAB with Hunt, HyAB, ^qc and the redistribution (FLIP.h:1883-1939).
  std::vector<float> difference(pixels);
  forRowBands(h, threads, [&](int y0, int y1) {
    std::vector<float> rows(8 * size_t(w));
    float* r[8];
    for (int i = 0; i < 8; ++i) r[i] = rows.data() + size_t(i) * size_t(w);
    for (int y = y0; y < y1; ++y) {
      filterRowY(hr.y, w, h, y, f.y, radius, r[0]);
      filterRowY(hr.cx, w, h, y, f.cx, radius, r[1]);
      filterRowY(hr.cz1, w, h, y, f.cz1, radius, r[2]);
      filterRowY(hr.cz2, w, h, y, f.cz2, radius, r[3]);
      filterRowY(ht.y, w, h, y, f.y, radius, r[4]);
      filterRowY(ht.cx, w, h, y, f.cx, radius, r[5]);
      filterRowY(ht.cz1, w, h, y, f.cz1, radius, r[6]);
      filterRowY(ht.cz2, w, h, y, f.cz2, radius, r[7]);
      for (int x = 0; x < w; ++x) {
        const auto lab = [](float y, float cx, float cz1, float cz2) {
          const Color rgb = xyzToLinearRGB(yCxCzToXYZ({y, cx, cz1 + cz2}));
          return huntLab({clamp01(rgb.x), clamp01(rgb.y), clamp01(rgb.z)});
        };
        float d = powf(hyAB(lab(r[0][x], r[1][x], r[2][x], r[3][x]), lab(r[4][x], r[5][x], r[6][x], r[7][x])), kQc);
        // Differences up to pc * cmax go to [0, pt], the rest to (pt, 1] (§4.2).
        if (d < pccmax) d *= kPt / pccmax;
        else d = kPt + ((d - pccmax) / (cmax - pccmax)) * (1.0f - kPt);
        difference[size_t(y) * size_t(w) + size_t(x)] = d;
      }
    }
  });
  return difference;
}

// Steps 5-6 (FLIP.h:1944-2043): feature differences on the unfiltered Y channel, normalised
// to [0, 1], and the final error.
void applyFeatureDifference(std::vector<float>& error, const Planes& ref, const Planes& test, int w, int h, float ppd,
                            int threads) {
  const FeatureFilter f = featureFilter(ppd);
  const int radius = featureFilterRadius(ppd);
  const size_t pixels = size_t(w) * size_t(h);
  const float oneOver116 = 1.0f / 116.0f;
  const float sixteenOver116 = 16.0f / 116.0f;

  // Horizontal: 1st and 2nd x-derivatives, and the Gaussian for the y-derivatives' pass, of
  // Y brought to [0, 1] (FLIP.h:1968-2001).
  struct Pass {
    std::vector<float> dx, ddx, g;
  };
  Pass hr{std::vector<float>(pixels), std::vector<float>(pixels), std::vector<float>(pixels)};
  Pass ht = hr;
  forRowBands(h, threads, [&](int y0, int y1) {
    std::vector<float> padded, normalized(static_cast<size_t>(w));
    for (int y = y0; y < y1; ++y) {
      const size_t row = size_t(y) * size_t(w);
      for (auto [in, out] : {std::pair{&ref, &hr}, std::pair{&test, &ht}}) {
        for (int x = 0; x < w; ++x) normalized[size_t(x)] = in->y[row + size_t(x)] * oneOver116 + sixteenOver116;
        filterRowX(normalized.data(), w, f.dg, radius, padded, out->dx.data() + row);
        filterRowX(normalized.data(), w, f.ddg, radius, padded, out->ddx.data() + row);
        filterRowX(normalized.data(), w, f.g, radius, padded, out->g.data() + row);
      }
    }
  });

  // Vertical: the Gaussian over the x-derivatives, the derivatives over the Gaussian; edge
  // and point strengths are the gradients' lengths (FLIP.h:2006-2042).
  const float normalizationFactor = 1.0f / std::sqrt(2.0f);
  forRowBands(h, threads, [&](int y0, int y1) {
    std::vector<float> rows(8 * size_t(w));
    float* r[8];
    for (int i = 0; i < 8; ++i) r[i] = rows.data() + size_t(i) * size_t(w);
    for (int y = y0; y < y1; ++y) {
      filterRowY(hr.dx, w, h, y, f.g, radius, r[0]);
      filterRowY(hr.ddx, w, h, y, f.g, radius, r[1]);
      filterRowY(hr.g, w, h, y, f.dg, radius, r[2]);
      filterRowY(hr.g, w, h, y, f.ddg, radius, r[3]);
      filterRowY(ht.dx, w, h, y, f.g, radius, r[4]);
      filterRowY(ht.ddx, w, h, y, f.g, radius, r[5]);
      filterRowY(ht.g, w, h, y, f.dg, radius, r[6]);
      filterRowY(ht.g, w, h, y, f.ddg, radius, r[7]);
      for (int x = 0; x < w; ++x) {
        const float edgeRef = std::sqrt(r[0][x] * r[0][x] + r[2][x] * r[2][x]);
        const float pointRef = std::sqrt(r[1][x] * r[1][x] + r[3][x] * r[3][x]);
        const float edgeTest = std::sqrt(r[4][x] * r[4][x] + r[6][x] * r[6][x]);
        const float pointTest = std::sqrt(r[5][x] * r[5][x] + r[7][x] * r[7][x]);
        const float edgeDifference = std::fabs(edgeRef - edgeTest);
        const float pointDifference = std::fabs(pointRef - pointTest);
        const float featureDifference =
            powf(normalizationFactor * (edgeDifference > pointDifference ? edgeDifference : pointDifference), kQf);
        float& e = error[size_t(y) * size_t(w) + size_t(x)];
        e = powf(e, 1.0f - featureDifference);   // §4.4: features raise the colour error
      }
    }
  });
}

}  // namespace

float flipPpd(float distance, float resolutionX, float monitorWidth) {
  return distance * (resolutionX / monitorWidth) * (kPi / 180.0f);   // FLIP.h:110-113
}

float flipDefaultPpd() { return flipPpd(0.7f, 3840.0f, 0.7f); }   // FLIP.h:118

std::vector<float> flipErrorMap(const std::vector<uint8_t>& reference, const std::vector<uint8_t>& test, int width,
                                int height, float ppd, int threads) {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument("flip: the image size " + std::to_string(width) + "x" + std::to_string(height) +
                                " is empty");
  const size_t pixels = size_t(width) * size_t(height);
  if (reference.size() != 4 * pixels || test.size() != 4 * pixels)
    throw std::invalid_argument("flip: an RGBA8 image of " + std::to_string(width) + "x" + std::to_string(height) +
                                " is " + std::to_string(4 * pixels) + " bytes; the reference has " +
                                std::to_string(reference.size()) + ", the test " + std::to_string(test.size()));
  if (!(ppd > 0.0f) || !std::isfinite(ppd))
    throw std::invalid_argument("flip: pixels per degree must be a positive number, not " + std::to_string(ppd));
  if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
  const Planes ref = toYCxCz(reference, pixels);
  const Planes tst = toYCxCz(test, pixels);
  std::vector<float> error = colorDifference(ref, tst, width, height, ppd, threads);
  applyFeatureDifference(error, ref, tst, width, height, ppd, threads);
  return error;
}

std::vector<float> flipErrorMap(const scenes::ImageData& reference, const scenes::ImageData& test, float ppd,
                                int threads) {
  const auto check = [](const scenes::ImageData& image, const char* which) {
    if (image.format != scenes::TexelFormat::RGBA8 || image.rgba8.empty() || !image.floats.empty() ||
        !image.depth.empty())
      throw std::invalid_argument(std::string("flip: the ") + which +
                                  " image is not RGBA8 colour; FLIP measures 8-bit sRGB colour only");
  };
  check(reference, "reference");
  check(test, "test");
  if (reference.width != test.width || reference.height != test.height)
    throw std::invalid_argument("flip: the images differ in size (" + std::to_string(reference.width) + "x" +
                                std::to_string(reference.height) + " and " + std::to_string(test.width) + "x" +
                                std::to_string(test.height) + ")");
  return flipErrorMap(reference.rgba8, test.rgba8, reference.width, reference.height, ppd, threads);
}

double flipMean(const std::vector<float>& errorMap) {
  // As the reference: a float sum in pixel order over a float count (FLIP.h:2461-2470, and
  // the FLIP tool's pooling<float>). A double sum is closer to the map's true mean (at 1080p
  // by ~5e-6), but then the mean would not read as the reference's six published decimals.
  float sum = 0.0f;
  for (float e : errorMap) sum += e;
  return errorMap.empty() ? 0.0 : double(sum / float(errorMap.size()));
}

double flipMean(const scenes::ImageData& reference, const scenes::ImageData& test, float ppd, int threads) {
  return flipMean(flipErrorMap(reference, test, ppd, threads));
}

}  // namespace compare
