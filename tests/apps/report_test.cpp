// The report's page writers (apps/report/report_*.h): escaping, the metrics and sidecar tables, the
// pixel-history panel on a hand-written trace (tests/apps/fixtures/report/), and the choice
// of pixels to trace. The whole report in a browser is tests/apps/report_chromium_test.py.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "apps/common/pixels_to_trace.h"
#include "apps/common/target_stats_json.h"
#include "apps/report/report_html.h"
#include "apps/report/report_results.h"
#include "apps/report/report_targets.h"
#include "apps/report/report_trace_panel.h"
#include "compare/metrics.h"

namespace {

using nlohmann::json;

json fixture(const std::string& name) {
  std::ifstream in(std::string(RASTER_SOURCE_DIR) + "/tests/apps/fixtures/report/" + name);
  REQUIRE(in.good());
  return json::parse(in);
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

scenes::ImageData rgba8(int width, int height) {
  scenes::ImageData image;
  image.width = width;
  image.height = height;
  image.rgba8.assign(size_t(width) * size_t(height) * 4, 100);
  return image;
}

}  // namespace

TEST_SUITE("report") {

TEST_CASE("every character that could open a tag or end an attribute is escaped") {
  CHECK(report::escape("<a href=\"x\" title='y'>&</a>") ==
        "&lt;a href=&quot;x&quot; title=&#39;y&#39;&gt;&amp;&lt;/a&gt;");
  CHECK(report::escape("plain_name-1.png") == "plain_name-1.png");
  report::Table t{"id\"x", "<cap>", {"<h>"}, {{report::escape("<td>")}}};
  const std::string html = t.html();
  CHECK(html.find("<cap>") == std::string::npos);
  CHECK(html.find("id=\"id&quot;x\"") != std::string::npos);
  CHECK(html.find("<td>&lt;td&gt;</td>") != std::string::npos);
  const std::string fig = report::figure("a\"b.png", "x<y", "d.exr", "d.exr");
  CHECK(fig.find("src=\"a&quot;b.png\"") != std::string::npos);
  CHECK(fig.find("x&lt;y") != std::string::npos);
}

TEST_CASE("JSON values read as short texts") {
  CHECK(report::jsonText(json(nullptr)) == "-");
  CHECK(report::jsonText(json(0.1 + 0.2)) == "0.3");
  CHECK(report::jsonText(json::array({1, 2.5, "a"})) == "[1, 2.5, a]");
  CHECK(report::jsonText(json(true)) == "yes");
}

TEST_CASE("the metrics table shows what the stats JSON holds") {
  scenes::ImageData a = rgba8(4, 2), b = rgba8(4, 2);
  b.rgba8[0] = 103;   // one pixel off by 3 steps
  const json stats = cli::targetStatsJson(compare::compareImages("final", a, b));
  CHECK(stats.at("kind") == "rgba8");
  CHECK(stats.at("max_abs").get<double>() == 3);
  const std::string html = report::metricsTable(stats, "metrics-x-final");
  const std::string psnr = report::psnrText(stats.at("psnr_db"));
  CHECK(html.find(">" + psnr + "</td>") != std::string::npos);
  CHECK(html.find("data-value=\"" + stats.at("psnr_db").dump() + "\"") != std::string::npos);
  CHECK(html.find("12.500%") != std::string::npos);   // 1 of 8 pixels differs

  const json same = cli::targetStatsJson(compare::compareImages("final", a, a));
  CHECK(same.at("psnr_db").is_null());
  CHECK(report::metricsTable(same, "m").find(">identical</td>") != std::string::npos);
  CHECK(!stats.contains("flip_mean"));   // FLIP is added only where it was measured

  compare::TargetStats measured = compare::compareImages("final", a, b);
  compare::measureFlip(measured, a, b);
  const json withFlip = cli::targetStatsJson(measured);
  REQUIRE(withFlip.at("flip_mean").is_number());
  CHECK(withFlip.at("flip_mean").get<double>() == *measured.flipMean);
  CHECK(withFlip.at("flip_mean").get<double>() > 0.0);
  CHECK(report::metricsTable(withFlip, "m").find("data-value=\"" + withFlip.at("flip_mean").dump() + "\"") !=
        std::string::npos);
}

TEST_CASE("a trace becomes a panel: every pass, fragment, sample and value, escaped") {
  const json trace = fixture("trace_deferred.json");
  const std::string html = report::tracePanel(trace, "trace-deferred-81-57");
  CHECK(html.find("id=\"trace-deferred-81-57\"") != std::string::npos);
  CHECK(count(html, "<details") == 1 + 2 + 1);   // the pixel, two passes, one sample's texels
  CHECK(html.find("pixel [81, 57]: 2 passes") != std::string::npos);
  CHECK(html.find("sampled by pass 3 at (0.5, 0.293)") != std::string::npos);
  CHECK(html.find("2 fragments") != std::string::npos);
  CHECK(html.find(">failed<") != std::string::npos);
  // The sample line and its four texels with weights.
  CHECK(html.find("g_albedo at [0.50625, 0.475] = [0.8, 0.6, 0.4, 1]") != std::string::npos);
  CHECK(count(html, "<td>0.25</td>") == 4);
  // Stored, GL and the difference, the non-zero difference marked.
  CHECK(html.find("<td>[204, 153, 102, 255]</td><td>[204, 153, 101, 255]</td><td class=\"diff\">[0, 0, 1, 0]</td>") !=
        std::string::npos);
  CHECK(html.find("final: ours [204, 153, 102, 255], GL [204, 153, 101, 255], difference [0, 0, 1, 0]") !=
        std::string::npos);
  // A program name with markup shows as text.
  CHECK(html.find("<b>odd name</b>") == std::string::npos);
  CHECK(html.find("&lt;b&gt;odd name&lt;/b&gt;") != std::string::npos);
  // The shadow pass has no reference: its GL cell reads "-".
  CHECK(html.find("<td>shadow_map</td><td>0.4375</td><td>-</td><td>-</td>") != std::string::npos);
}

TEST_CASE("a trace with fields missing still makes a panel") {
  const json sparse = {{"pixel", {1, 2}}, {"passes", json::array({json::object({{"pass", 0}}), json(5)})}};
  std::string html;
  CHECK_NOTHROW(html = report::tracePanel(sparse, "t"));
  CHECK(html.find("pixel [1, 2]: 2 passes") != std::string::npos);
  CHECK(html.find("No fragment reached this pixel") != std::string::npos);
  CHECK_NOTHROW(report::tracePanel(json("not an object"), "t"));
}

TEST_CASE("a sidecar's scalars are a table, its nested values JSON text") {
  const json sidecar = {{"view", "overdraw"}, {"max", 7}, {"legend", {{"0", "black"}}}};
  const std::string html = report::sidecarTable(sidecar, "view-x");
  CHECK(html.find("<td>view</td><td>overdraw</td>") != std::string::npos);
  CHECK(html.find("data-value=\"7\"") != std::string::npos);
  CHECK(html.find("<summary>legend</summary><pre>") != std::string::npos);
}

TEST_CASE("the traced pixels: the worst differing first, ties by position, then interior points") {
  scenes::ImageData ours = rgba8(8, 4), gl = rgba8(8, 4);
  const auto set = [&](int x, int y, int channel, uint8_t value) { ours.rgba8[(size_t(y) * 8 + size_t(x)) * 4 + size_t(channel)] = value; };
  set(6, 3, 0, 105);   // off by 5
  set(1, 2, 2, 110);   // off by 10
  set(5, 0, 1, 105);   // off by 5, before (6, 3) by position
  const std::vector<cli::ChosenPixel> three = cli::choosePixels(ours, gl, 3);
  REQUIRE(three.size() == 3);
  CHECK((three[0].x == 1 && three[0].y == 2 && three[0].difference == 10));
  CHECK((three[1].x == 5 && three[1].y == 0 && three[1].difference == 5));
  CHECK((three[2].x == 6 && three[2].y == 3));

  const std::vector<cli::ChosenPixel> five = cli::choosePixels(ours, gl, 5);
  REQUIRE(five.size() == 5);
  CHECK((five[3].x == 4 && five[3].y == 2 && five[3].difference == 0));   // the centre
  CHECK((five[4].x == 2 && five[4].y == 1));                              // a quarter point

  const std::vector<cli::ChosenPixel> none = cli::choosePixels(gl, gl, 2);
  REQUIRE(none.size() == 2);
  CHECK((none[0].x == 4 && none[0].y == 2));
  CHECK(cli::choosePixels(gl, gl, 0).empty());
  // A one-pixel image has one pixel to give.
  CHECK(cli::choosePixels(rgba8(1, 1), rgba8(1, 1), 5).size() == 1);
}

TEST_CASE("an RGBA8 preview is opaque, and its alpha, which is data, is a grey image of its own") {
  scenes::ImageData gbuffer = rgba8(2, 1);
  gbuffer.rgba8 = {200, 150, 100, 0, 10, 20, 30, 72};   // alpha: specular intensity, not coverage
  CHECK(report::alphaIsData(gbuffer));
  const scenes::ImageData colour = report::opaqueColour(gbuffer);
  CHECK(colour.width == 2);
  CHECK(colour.rgba8 == std::vector<uint8_t>{200, 150, 100, 255, 10, 20, 30, 255});
  const scenes::ImageData alpha = report::alphaAsGrey(gbuffer);
  CHECK(alpha.rgba8 == std::vector<uint8_t>{0, 0, 0, 255, 72, 72, 72, 255});
  // Float and depth targets have no alpha to show apart (their previews drop it).
  scenes::ImageData half = gbuffer;
  half.format = scenes::TexelFormat::RGBA16F;
  CHECK(!report::alphaIsData(half));
  scenes::ImageData depth;
  depth.format = scenes::TexelFormat::Depth24;
  depth.channels = 1;
  CHECK(!report::alphaIsData(depth));
}

}  // TEST_SUITE
