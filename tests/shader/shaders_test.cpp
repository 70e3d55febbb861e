// Shader ports: the SIMD instantiations (Float8, and Float8x2 for two groups at once) and
// the plain C++ one (Lanes<8>) of every port agree bit for bit, vertex and fragment, on
// random inputs. Each lane type computes every operation as the same single IEEE float32
// operation, so no ULP allowance is needed.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include "raster/methods.h"
#include "raster/texture/format.h"
#include "shaders_cpp/deferred/gbuffer.h"
#include "shaders_cpp/deferred/ssao.h"
#include "shaders_cpp/hdr/scene.h"
#include "shaders_cpp/pbr/ssao.h"
#include "shaders_cpp/shadow/main.h"
#include "shaders_cpp/shadow/shadow.h"
#include "tests/method_sets.h"

namespace {

using Fast = raster::simd::FastLanes;
using Plain = raster::simd::Lanes<8>;

template <class F>
F lanesFrom(const float (&values)[8]) {
  return F::load(values);
}

bool sameBits(const float* a, const float* b, int n) { return std::memcmp(a, b, sizeof(float) * size_t(n)) == 0; }

template <class F>
void storeVec4(const raster::glsl::vec4<F>& v, float out[4][8]) {
  v.x.store(out[0]);
  v.y.store(out[1]);
  v.z.store(out[2]);
  v.w.store(out[3]);
}

// Runs Program::vertex on both lane types with the same random attributes.
template <class Program>
void checkVertexAgrees(const typename Program::Uniforms& u, std::mt19937& rng) {
  std::uniform_real_distribution<float> value(-3.0f, 3.0f);
  raster::VertexInput<Fast> fastIn;
  raster::VertexInput<Plain> plainIn;
  for (int a = 0; a < raster::limits::kMaxVertexAttributes; ++a) {
    float comps[4][8];
    for (auto& c : comps)
      for (float& x : c) x = value(rng);
    fastIn.attribute[a] = {lanesFrom<Fast>(comps[0]), lanesFrom<Fast>(comps[1]), lanesFrom<Fast>(comps[2]), lanesFrom<Fast>(comps[3])};
    plainIn.attribute[a] = {lanesFrom<Plain>(comps[0]), lanesFrom<Plain>(comps[1]), lanesFrom<Plain>(comps[2]), lanesFrom<Plain>(comps[3])};
  }
  fastIn.gl_InstanceID = Fast(0.0f);
  plainIn.gl_InstanceID = Plain(0.0f);
  raster::glsl::vec4<Fast> fastPos;
  raster::glsl::vec4<Plain> plainPos;
  typename Program::template Varyings<Fast> fastOut;
  typename Program::template Varyings<Plain> plainOut;
  Program::vertex(u, fastIn, fastPos, fastOut);
  Program::vertex(u, plainIn, plainPos, plainOut);
  float a[4][8], b[4][8];
  storeVec4(fastPos, a);
  storeVec4(plainPos, b);
  CHECK(sameBits(&a[0][0], &b[0][0], 32));
  constexpr int n = raster::varyingFloatCount<Program>();
  Fast fv[n > 0 ? n : 1];
  Plain pv[n > 0 ? n : 1];
  raster::varyingsToArray<Program, Fast>(fastOut, fv);
  raster::varyingsToArray<Program, Plain>(plainOut, pv);
  for (int i = 0; i < n; ++i) {
    float x[8], y[8];
    fv[i].store(x);
    pv[i].store(y);
    CHECK(sameBits(x, y, 8));
  }
}

// Runs Program::fragment with the same random varyings on the plain lanes, on the SIMD
// lanes, and (AVX2) on two SIMD groups paired as one Float8x2 call, as the pipeline shades
// texture-reading programs.
template <class Program>
void checkFragmentAgrees(const typename Program::Uniforms& u, std::mt19937& rng, float lo, float hi) {
  constexpr int n = raster::varyingFloatCount<Program>();
  std::uniform_real_distribution<float> value(lo, hi);
  float lanes[2][n > 0 ? n : 1][8];   // two groups' varyings
  for (auto& group : lanes)
    for (int i = 0; i < n; ++i)
      for (float& x : group[i]) x = value(rng);
  float plain[2][raster::limits::kMaxColorOutputs][4][8];
  for (int g = 0; g < 2; ++g) {
    Plain pv[n > 0 ? n : 1];
    for (int i = 0; i < n; ++i) pv[i] = lanesFrom<Plain>(lanes[g][i]);
    raster::FragmentInput<Plain> plainIn;
    plainIn.gl_FragCoord = {Plain(0.5f), Plain(0.5f), Plain(0.5f), Plain(1.0f)};
    raster::FragmentOutput<Plain> plainOut;
    Program::fragment(u, plainIn, raster::varyingsFromArray<Program, Plain>(pv), plainOut);
    for (int k = 0; k < Program::kColorOutputs; ++k) storeVec4(plainOut.color[k], plain[g][k]);
  }

  Fast fv[n > 0 ? n : 1];
  for (int i = 0; i < n; ++i) fv[i] = lanesFrom<Fast>(lanes[0][i]);
  raster::FragmentInput<Fast> fastIn;
  fastIn.gl_FragCoord = {Fast(0.5f), Fast(0.5f), Fast(0.5f), Fast(1.0f)};
  raster::FragmentOutput<Fast> fastOut;
  Program::fragment(u, fastIn, raster::varyingsFromArray<Program, Fast>(fv), fastOut);
  for (int k = 0; k < Program::kColorOutputs; ++k) {
    float a[4][8];
    storeVec4(fastOut.color[k], a);
    CHECK(sameBits(&a[0][0], &plain[0][k][0][0], 32));
  }

#if RASTER_AVX2
  using Paired = raster::simd::Float8x2;
  using raster::simd::Float8;
  Paired qv[n > 0 ? n : 1];
  for (int i = 0; i < n; ++i) qv[i] = {Float8::load(lanes[0][i]), Float8::load(lanes[1][i])};
  raster::FragmentInput<Paired> pairedIn;
  pairedIn.gl_FragCoord = {Paired(0.5f), Paired(0.5f), Paired(0.5f), Paired(1.0f)};
  raster::FragmentOutput<Paired> pairedOut;
  Program::fragment(u, pairedIn, raster::varyingsFromArray<Program, Paired>(qv), pairedOut);
  for (int k = 0; k < Program::kColorOutputs; ++k) {
    const raster::glsl::vec4<Paired>& c = pairedOut.color[k];
    float a[4][8], b[4][8];
    storeVec4(raster::glsl::vec4<Float8>(c.x.low(), c.y.low(), c.z.low(), c.w.low()), a);
    storeVec4(raster::glsl::vec4<Float8>(c.x.high(), c.y.high(), c.z.high(), c.w.high()), b);
    CHECK(sameBits(&a[0][0], &plain[0][k][0][0], 32));
    CHECK(sameBits(&b[0][0], &plain[1][k][0][0], 32));
  }
#endif
}

#if RASTER_AVX2
// A port that says its lanes are independent (raster::lanesIndependent) must shade each
// lane as if alone: the visibility pass then gathers the lanes of several triangles into
// one call (tile/visible_first.h). Sixteen lanes of random varyings, with zeros, denormals,
// infinities and NaNs among them, are shaded as one Float8x2 call; then each lane again with
// its inputs in every lane, and all sixteen once more in reverse order. Every output must
// keep its bits.
template <class Program>
void checkLanesIndependent(const typename Program::Uniforms& u, std::mt19937& rng) {
  static_assert(raster::lanesIndependent<Program>());
  using Paired = raster::simd::Float8x2;
  constexpr int n = raster::varyingFloatCount<Program>();
  const float specials[] = {0.0f, -0.0f, 1e-40f, -1e-40f, 1e30f, -1e30f, __builtin_inff(), -__builtin_inff(), __builtin_nanf("")};
  std::uniform_real_distribution<float> value(-3.0f, 3.0f);
  alignas(64) float inputs[n + 4][16];   // the varyings, then gl_FragCoord
  for (auto& input : inputs)
    for (float& x : input) x = rng() % 8 == 0 ? specials[rng() % std::size(specials)] : value(rng);
  // Shades lane `at(l)` of the inputs in lane l, returning every output channel's 16 lanes.
  auto shade = [&](auto at) {
    alignas(64) float lanes[n + 4][16];
    for (int v = 0; v < n + 4; ++v)
      for (int l = 0; l < 16; ++l) lanes[v][l] = inputs[v][at(l)];
    Paired varyings[n];
    for (int v = 0; v < n; ++v) varyings[v] = Paired::load(lanes[v]);
    raster::FragmentInput<Paired> in;
    in.gl_FragCoord = {Paired::load(lanes[n]), Paired::load(lanes[n + 1]), Paired::load(lanes[n + 2]), Paired::load(lanes[n + 3])};
    raster::FragmentOutput<Paired> out;
    Program::fragment(u, in, raster::varyingsFromArray<Program, Paired>(varyings), out);
    std::vector<float> result;
    for (int k = 0; k < Program::kColorOutputs; ++k)
      for (const Paired& c : {out.color[k].x, out.color[k].y, out.color[k].z, out.color[k].w}) {
        alignas(64) float all[16];
        c.store(all);
        result.insert(result.end(), all, all + 16);
      }
    return result;
  };
  const std::vector<float> together = shade([](int l) { return l; });
  const std::vector<float> reversed = shade([](int l) { return 15 - l; });
  for (int l = 0; l < 16; ++l) {
    const std::vector<float> alone = shade([&](int) { return l; });
    for (size_t c = 0; c < together.size() / 16; ++c) {
      CHECK(sameBits(&together[c * 16 + size_t(l)], &reversed[c * 16 + size_t(15 - l)], 1));
      CHECK(sameBits(&together[c * 16 + size_t(l)], &alone[c * 16 + size_t(l)], 1));
    }
  }
}
#endif

glm::mat4 randomMatrix(std::mt19937& rng) {
  std::uniform_real_distribution<float> value(-2.0f, 2.0f);
  glm::mat4 m;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = value(rng);
  return m;
}

// One lane's value for the sparse projections' tests: a quarter of the time a special float
// (both zeros, denormals, the largest floats, infinities, NaN, 1 and -2.5), else one drawn
// from `ordinary`.
float specialOr(std::mt19937& rng, std::uniform_real_distribution<float>& ordinary) {
  static constexpr float kInf = std::numeric_limits<float>::infinity(), kNaN = std::numeric_limits<float>::quiet_NaN();
  static constexpr float kSpecial[] = {0.0f, -0.0f, 1e-45f, -1e-40f, 1e-30f, 3.4e38f, -3.4e38f, kInf, -kInf, kNaN, 1.0f, -2.5f};
  if (rng() % 4 != 0) return ordinary(rng);
  return kSpecial[rng() % std::size(kSpecial)];
}

}  // namespace

TEST_SUITE("shaders") {
  // Under every method set (tests/method_sets.h): each method's SIMD code is held to its
  // plain-lane reference, not only gl's.
  TEST_CASE("shadow/shadow: SIMD and plain lanes agree bit for bit") {
    for (const raster::MethodSet& set : testing_support::everyMethodSet()) {
      const raster::ScopedMethods scoped(set);
      INFO("methods " << raster::methodLabel(set));
      std::mt19937 rng(11);
      for (int round = 0; round < 200; ++round) {
        shaders::shadow::ShadowPass::Uniforms u;
        u.u_light_vp = randomMatrix(rng);
        u.u_model = randomMatrix(rng);
        checkVertexAgrees<shaders::shadow::ShadowPass>(u, rng);
        checkFragmentAgrees<shaders::shadow::ShadowPass>(u, rng, -1.0f, 1.0f);
      }
    }
  }

  TEST_CASE("shadow/main: SIMD and plain lanes agree bit for bit") {
    for (const raster::MethodSet& set : testing_support::everyMethodSet()) {
      const raster::ScopedMethods scoped(set);
      INFO("methods " << raster::methodLabel(set));
      std::mt19937 rng(12);
      raster::Texture shadowMap(64, 64, raster::TexelFormat::Depth24);
      std::uniform_int_distribution<uint32_t> code(0, raster::format::kDepth24Max);
      for (uint32_t& texel : shadowMap.depth) texel = code(rng);
      std::uniform_real_distribution<float> value(-3.0f, 3.0f);
      for (int round = 0; round < 400; ++round) {
        shaders::shadow::MainPass::Uniforms u;
        u.u_light_vp = randomMatrix(rng);
        u.u_model = randomMatrix(rng);
        u.u_view = randomMatrix(rng);
        u.u_proj = randomMatrix(rng);
        u.u_light_dir = {value(rng), value(rng), value(rng)};
        u.u_cam_pos = {value(rng), value(rng), value(rng)};
        u.u_is_floor = float(round % 2);
        u.shadow_map.texture = &shadowMap;
        checkVertexAgrees<shaders::shadow::MainPass>(u, rng);
        checkFragmentAgrees<shaders::shadow::MainPass>(u, rng, -2.0f, 2.0f);
      }
    }
  }

  // deferred/post+ssao leaves u_proj's zero entries out of each sample's projection
  // (SsaoPass::projectSample). What the sample reads of clip (the texture coordinate, the
  // test clip.w > 0, and wv) must be the full product's bits wherever its guard stays 0, for
  // the special values a view-space point can hold (specialOr).
  TEST_CASE("deferred/post+ssao: the sparse projection reads as the full one wherever it vouches for a lane") {
    using Ssao = shaders::deferred::SsaoPass;
    std::mt19937 rng(14);
    std::uniform_real_distribution<float> value(-30.0f, 30.0f);
    const glm::mat4 view = glm::lookAtRH(glm::vec3(4.0f, 3.0f, 6.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    int vouched = 0, refused = 0;
    for (const float nearPlane : {0.1f, 1e-6f, 5.0f}) {
      const glm::mat4 proj = glm::perspectiveRH_NO(1.0f, 4.0f / 3.0f, nearPlane, 60.0f);
      REQUIRE(Ssao::hasSparseProjection(proj, view));
      for (int round = 0; round < 4000; ++round) {
        float c[4][8];
        for (auto& component : c)
          for (float& x : component) x = specialOr(rng, value);
        for (int lane = 0; lane < 8; ++lane) c[3][lane] = 1.0f;   // u_view's w row makes vw 1 (hasSparseProjection)
        const raster::glsl::vec4<Plain> v(lanesFrom<Plain>(c[0]), lanesFrom<Plain>(c[1]), lanesFrom<Plain>(c[2]),
                                          lanesFrom<Plain>(c[3]));
        Plain guard(0.0f), unused(0.0f);
        const auto full = Ssao::projectSample<false>(proj, v, unused);
        const auto sparse = Ssao::projectSample<true>(proj, v, guard);
        for (int lane = 0; lane < 8; ++lane) {
          const bool finite = std::isfinite(c[0][lane]) && std::isfinite(c[1][lane]) && std::isfinite(c[2][lane]);
          if (!finite) CHECK(guard.lane[lane] != 0.0f);   // NaN: a non-finite operand is always refused
          if (guard.lane[lane] != 0.0f) {
            ++refused;
            continue;
          }
          ++vouched;
          auto reads = [&](const raster::glsl::vec4<Plain>& clip) {
            const float x = clip.x.lane[lane], y = clip.y.lane[lane], w = clip.w.lane[lane];
            const float wv = w > 0.0001f ? w : 0.0001f;   // GLSL max(clip.w, 0.0001), as the lanes' max
            return std::array<float, 4>{x / wv * 0.5f + 0.5f, y / wv * 0.5f + 0.5f, wv, w > 0.0f ? 1.0f : 0.0f};
          };
          const std::array<float, 4> a = reads(full), b = reads(sparse);
          INFO("view point (" << c[0][lane] << ", " << c[1][lane] << ", " << c[2][lane] << "), near " << nearPlane);
          CHECK(sameBits(a.data(), b.data(), 4));
        }
      }
    }
    CHECK(vouched > 10000);
    CHECK(refused > 1000);
  }

  // pbr/post+ssao leaves out the zero entries of uProjection (each sample's point) and of
  // uInvProjection (its depth lookup's view z): the texture coordinate a sample looks up and
  // the view z it makes must be the full products' bits wherever the guard (`check`) stays
  // 0, for the same special values (specialOr), with the depth lookup's z among them.
  TEST_CASE("pbr/post+ssao: the sparse projections read as the full ones wherever the guard stays 0") {
    using Ssao = shaders::pbr::SsaoPass;
    std::mt19937 rng(15);
    std::uniform_real_distribution<float> value(-30.0f, 30.0f), depth(-1.0f, 1.0f);
    int vouched = 0, refused = 0;
    for (const float nearPlane : {0.1f, 1e-6f, 5.0f}) {
      const glm::mat4 proj = glm::perspectiveRH_NO(1.0f, 4.0f / 3.0f, nearPlane, 60.0f), inverse = glm::inverse(proj);
      REQUIRE(Ssao::hasSparseProjections(proj, inverse));
      for (int round = 0; round < 4000; ++round) {
        float c[4][8];
        for (int lane = 0; lane < 8; ++lane) {
          for (int k = 0; k < 3; ++k) c[k][lane] = specialOr(rng, value);
          c[3][lane] = specialOr(rng, depth);
        }
        const raster::glsl::vec3<Plain> samplePos(lanesFrom<Plain>(c[0]), lanesFrom<Plain>(c[1]), lanesFrom<Plain>(c[2]));
        const Plain z = lanesFrom<Plain>(c[3]);
        Plain check(0.0f), unused(0.0f);
        // What the sample makes of its projection: the lookup's uv (as the port's loop) and
        // the view z of the texel there, here with the drawn z for its depth.
        auto sample = [&](auto sparse, Plain& guard) {
          constexpr bool kSparse = decltype(sparse)::value;
          const auto o = Ssao::projectSample<kSparse>(proj, samplePos, guard);
          const raster::glsl::vec2<Plain> uv(o.x / o.z * Plain(0.5f) + Plain(0.5f), o.y / o.z * Plain(0.5f) + Plain(0.5f));
          const Plain viewZ = Ssao::viewZFromClip<kSparse>(inverse, Ssao::clipXY(uv), z, guard);
          return std::array<Plain, 3>{uv.x, uv.y, viewZ};
        };
        const std::array<Plain, 3> full = sample(std::false_type{}, unused), sparse = sample(std::true_type{}, check);
        for (int lane = 0; lane < 8; ++lane) {
          const bool finite = std::isfinite(c[0][lane]) && std::isfinite(c[1][lane]) && std::isfinite(c[2][lane]) &&
                              std::isfinite(c[3][lane]);
          if (!finite) CHECK(check.lane[lane] != 0.0f);   // NaN: a non-finite operand is always refused
          if (check.lane[lane] != 0.0f) {
            ++refused;
            continue;
          }
          ++vouched;
          INFO("sample point (" << c[0][lane] << ", " << c[1][lane] << ", " << c[2][lane] << "), z " << c[3][lane]
                                << ", near " << nearPlane);
          for (int k = 0; k < 3; ++k) CHECK(sameBits(&full[size_t(k)].lane[lane], &sparse[size_t(k)].lane[lane], 1));
        }
      }
    }
    CHECK(vouched > 10000);
    CHECK(refused > 1000);
  }

  // Ports that read derivatives or textures keep the default: their lane groups are never
  // gathered from several triangles.
  static_assert(!raster::lanesIndependent<shaders::deferred::GBufferPass>());
  static_assert(!raster::lanesIndependent<shaders::shadow::MainPass>());

#if RASTER_AVX2
  TEST_CASE("hdr/scene says its lanes are independent, and shades each lane as if alone") {
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> value(-3.0f, 3.0f);
    for (int round = 0; round < 100; ++round) {
      shaders::hdr::ScenePass::Uniforms u;
      u.u_view = randomMatrix(rng);
      u.u_proj = randomMatrix(rng);
      u.u_time = value(rng);
      u.u_cam_pos = {value(rng), value(rng), value(rng)};
      checkLanesIndependent<shaders::hdr::ScenePass>(u, rng);
    }
  }
#endif
}
