// Texel planes (shader/texel_planes.h): a plane read at any coordinate gives the bits its
// function gives there, in every lane type, on every wrap and at odd sizes; a plane is made
// only where that holds; and a traced lane still makes its lookups.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

#include "raster/methods.h"
#include "raster/shader/texel_planes.h"
#include "raster/simd/glsl.h"
#include "tests/texture/lookup_test_helpers.h"

using namespace gltest;

namespace {

using namespace raster::glsl;

// A port's uniforms with the shape of SSAO's: two NEAREST sources and a matrix, and the
// plane made of them.
struct Uniforms {
  glm::mat4 view{1.0f};
  raster::Sampler2D positions, normals;
  raster::TexelPlane plane;
};

// SSAO's storedViewZ: a view-space z of one texel, NaN where the other texel is short.
template <class F>
F storedViewZ(const Uniforms& u, vec2<F> uv) {
  const vec3<F> p = raster::texture(u.positions, uv).xyz();
  const vec3<F> n = raster::texture(u.normals, uv).xyz();
  const F z = (u.view * vec4<F>(p, F(1.0f))).z;
  return select(dot(n, n) > F(64.0f), z, F(std::numeric_limits<float>::quiet_NaN()));
}

void makePlane(Uniforms& u, raster::ThreadPool& pool, const raster::Framebuffer& target, bool scalarLanes) {
  raster::TexelPlaneMaker<Uniforms> make(u, pool, target, scalarLanes);
  make(&Uniforms::plane, {&Uniforms::positions, &Uniforms::normals},
       [](const Uniforms& uniforms, auto uv) { return storedViewZ(uniforms, uv); });
}

// Lanes of F at random coordinates (laneCoordinate: NaN, infinities, far outside, edges):
// the plane's value against the function's, bit for bit; NaN matches NaN.
template <class F>
long mismatchesOver(const Uniforms& u, std::mt19937& rng, int rounds) {
  long mismatches = 0;
  for (int round = 0; round < rounds; ++round) {
    alignas(64) float s[F::kCount], t[F::kCount], got[F::kCount], want[F::kCount];
    for (int i = 0; i < F::kCount; ++i) s[i] = laneCoordinate(rng), t[i] = laneCoordinate(rng);
    const vec2<F> uv(F::load(s), F::load(t));
    raster::textureFromPlane(u.plane, uv, [&](vec2<F> at) { return storedViewZ(u, at); }).store(got);
    storedViewZ(u, uv).store(want);
    for (int i = 0; i < F::kCount; ++i) mismatches += !sameLookup(got[i], want[i]);
  }
  return mismatches;
}

}  // namespace

TEST_SUITE("texture") {
  TEST_CASE("a texel plane read anywhere gives its function's bits, in every lane type, wrap and size") {
    std::mt19937 rng(2026);
    raster::ThreadPool pool(2);
    const raster::Framebuffer elsewhere;   // the draw's target: neither source
    long nans = 0, numbers = 0;            // texels on each side of the function's select
    for (const auto& [w, h] : {std::pair{13, 7}, std::pair{1, 1}, std::pair{64, 3}, std::pair{3, 1001}, std::pair{16384, 1}}) {
      raster::Texture positions = randomTexture(rng, w, h, raster::TexelFormat::RGBA16F);
      raster::Texture normals = randomTexture(rng, w, h, raster::TexelFormat::RGBA16F);
      for (raster::Wrap ws : {raster::Wrap::Repeat, raster::Wrap::ClampToEdge})
        for (raster::Wrap wt : {raster::Wrap::Repeat, raster::Wrap::ClampToEdge})
          for (bool scalarLanes : {false, true}) {
            CAPTURE(w);
            CAPTURE(h);
            CAPTURE(scalarLanes);
            positions.sampler = normals.sampler = {raster::Filter::Nearest, ws, wt, false};
            Uniforms u;
            u.view = glm::mat4(0.5f, -1.0f, 2.0f, 0.0f, 1.5f, 0.25f, -3.0f, 0.0f, -0.75f, 2.0f, 1.0f, 0.0f, 4.0f, -2.0f, 0.5f, 1.0f);
            u.positions.texture = &positions;
            u.normals.texture = &normals;
            makePlane(u, pool, elsewhere, scalarLanes);
            REQUIRE(u.plane.made());
            for (float v : u.plane.values) ++(std::isnan(v) ? nans : numbers);
            CHECK(mismatchesOver<raster::ScalarLanes>(u, rng, 300) == 0);
            CHECK(mismatchesOver<raster::FastLanes>(u, rng, 300) == 0);
#if RASTER_AVX2
            CHECK(mismatchesOver<raster::PairedLanes>(u, rng, 300) == 0);
#endif
          }
    }
    CHECK(nans > 1000);
    CHECK(numbers > 1000);
  }

  TEST_CASE("a texel plane is made only where its sources allow; otherwise the function runs at every lookup") {
    std::mt19937 rng(7);
    raster::ThreadPool pool(2);
    raster::Texture positions = randomTexture(rng, 32, 16, raster::TexelFormat::RGBA16F);
    raster::Texture normals = randomTexture(rng, 32, 16, raster::TexelFormat::RGBA16F);
    raster::Texture narrow = randomTexture(rng, 31, 16, raster::TexelFormat::RGBA16F);
    const raster::SamplerState nearest{raster::Filter::Nearest, raster::Wrap::ClampToEdge, raster::Wrap::ClampToEdge, false};
    positions.sampler = normals.sampler = narrow.sampler = nearest;
    const raster::Framebuffer elsewhere;
    auto planeFor = [&](raster::Texture& second, const raster::Framebuffer& target) {
      Uniforms u;
      u.positions.texture = &positions;
      u.normals.texture = &second;
      makePlane(u, pool, target, false);
      CHECK(mismatchesOver<raster::FastLanes>(u, rng, 50) == 0);   // made or not, the same bits
      return u.plane.made();
    };
    CHECK(planeFor(normals, elsewhere));
    CHECK_FALSE(planeFor(narrow, elsewhere));   // sizes differ: no one index serves both
    normals.sampler.wrapS = raster::Wrap::Repeat;
    CHECK_FALSE(planeFor(normals, elsewhere));   // wraps differ
    normals.sampler = nearest;
    normals.sampler.filter = raster::Filter::Linear;
    CHECK_FALSE(planeFor(normals, elsewhere));   // a bilinear lookup blends four texels
    {
      raster::MethodSet methods;   // lookup=nearest: every colour lookup is NEAREST
      methods.lookup = raster::LookupMethod::Nearest;
      const raster::ScopedMethods scoped(methods);
      CHECK(planeFor(normals, elsewhere));
    }
    normals.sampler = nearest;
    raster::Framebuffer writesNormals;   // the pass may still write the source
    writesNormals.colors = {&normals};
    writesNormals.width = 32;
    writesNormals.height = 16;
    CHECK_FALSE(planeFor(normals, writesNormals));
    Uniforms unbound;
    unbound.positions.texture = &positions;
    makePlane(unbound, pool, elsewhere, false);
    CHECK_FALSE(unbound.plane.made());
  }

  TEST_CASE("a lane that pixel history traces makes its texture lookups, plane or not") {
    std::mt19937 rng(11);
    raster::ThreadPool pool(1);
    raster::Texture positions = randomTexture(rng, 8, 8, raster::TexelFormat::RGBA16F);
    raster::Texture normals = randomTexture(rng, 8, 8, raster::TexelFormat::RGBA16F);
    positions.sampler = normals.sampler = {raster::Filter::Nearest, raster::Wrap::ClampToEdge, raster::Wrap::ClampToEdge, false};
    Uniforms u;
    u.positions.texture = &positions;
    u.normals.texture = &normals;
    makePlane(u, pool, raster::Framebuffer{}, true);
    REQUIRE(u.plane.made());
    raster::sampling::SampleTrace trace;
    raster::sampling::tActiveSampleTrace = &trace;
    const vec2<raster::ScalarLanes> uv(raster::ScalarLanes(0.3f), raster::ScalarLanes(0.6f));
    const raster::ScalarLanes got = raster::textureFromPlane(u.plane, uv, [&](auto at) { return storedViewZ(u, at); });
    raster::sampling::tActiveSampleTrace = nullptr;
    CHECK(trace.records.size() == 2);   // the two sources, as the GLSL reads them
    CHECK(sameLookup(got[0], raster::sampling::lookupPlane(u.plane, vec2<float>(0.3f, 0.6f))));
  }
}
