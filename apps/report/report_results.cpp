// Result tables of the report, from their JSON (report_results.h).
#include "apps/report/report_results.h"

#include <algorithm>
#include <vector>

#include "apps/report/report_html.h"
#include "apps/common/number_text.h"
#include "apps/common/target_stats_json.h"

namespace report {
namespace {

using nlohmann::json;

std::string percent(double share) { return cli::fixedDigits(100.0 * share, 3) + "%"; }

// A number cell: `shown` from `value`, the value itself in data-value.
std::string cell(const json& value, const std::string& shown) { return numberCell(shown, value); }

}  // namespace

std::string psnrText(const json& db) { return db.is_null() ? "identical" : cli::fixedDigits(db.get<double>(), 2); }

std::string metricsTable(const json& s, const std::string& id) {
  const std::string kind = s.at("kind");
  // The unit of a difference, as compare/metrics.h defines it per kind.
  const std::string unit = kind == "depth" ? "depth LSBs" : compare::TargetStats::isFloatKindName(kind) ? "float value" : "8-bit steps";
  Table t{id, "", {"metric", "value"}, {}};
  t.rows.push_back({escape("size"), escape(jsonText(s.at("size")[0]) + "x" + jsonText(s.at("size")[1]))});
  t.rows.push_back({escape("largest difference (" + unit + ")"), cell(s.at("max_abs"), cli::sixDigits(s.at("max_abs")))});
  t.rows.push_back({escape("RMSE (" + unit + ")"), cell(s.at("rmse"), cli::sixDigits(s.at("rmse")))});
  t.rows.push_back({escape("PSNR (dB)"), cell(s.at("psnr_db"), psnrText(s.at("psnr_db")))});
  if (s.contains("flip_mean") && !s.at("flip_mean").is_null())
    t.rows.push_back({escape("FLIP mean (0: no visible difference, 1: the most)"),
                      cell(s.at("flip_mean"), cli::fixedDigits(s.at("flip_mean").get<double>(), 6))});
  t.rows.push_back({escape("pixels differing"), cell(s.at("share_differing"), percent(s.at("share_differing")))});
  t.rows.push_back({escape("pixels off by > 1"), cell(s.at("share_over1"), percent(s.at("share_over1")))});
  t.rows.push_back({escape("pixels off by > 4"), cell(s.at("share_over4"), percent(s.at("share_over4")))});
  if (kind == "depth") {
    t.rows.push_back({escape("texels differing"), cell(s.at("depth_texels_differing"), jsonText(s.at("depth_texels_differing")))});
  }
  if (compare::TargetStats::isFloatKindName(kind)) {
    const std::string ulps = cli::ulpsKey(kind);
    t.rows.push_back({escape("pixels bit-identical"), cell(s.at("share_bit_identical"), percent(s.at("share_bit_identical")))});
    t.rows.push_back({escape("largest difference (" + kind + " ULPs)"), cell(s.at(ulps), jsonText(s.at(ulps)))});
    t.rows.push_back({escape("non-finite pixels"), cell(s.at("nonfinite_pixels"), jsonText(s.at("nonfinite_pixels")))});
  }
  return t.html();
}

std::string tradeoffTables(const json& tradeoff, const std::string& idPrefix) {
  const json results = tradeoff.is_array() ? tradeoff : json::array({tradeoff});
  std::string out;
  for (const json& result : results) {
    std::vector<json> points(result.at("points").begin(), result.at("points").end());
    std::stable_sort(points.begin(), points.end(), [](const json& a, const json& b) {
      return a.at("speedup_vs_llvmpipe").get<double>() > b.at("speedup_vs_llvmpipe").get<double>();
    });
    const std::string scene = result.at("scene");
    Table t{idPrefix + "-" + scene,
            scene + ", " + jsonText(result.at("size")[0]) + "x" + jsonText(result.at("size")[1]) + ", t=" +
                jsonText(result.at("time")) + ", " + jsonText(result.at("threads")) + " threads",
            {"point", "kind", "median ms", "speed-up vs llvmpipe", "PSNR vs llvmpipe (dB)", "pixels off > 1",
             "max diff", "PSNR vs precise (dB)", "Pareto"},
            {}};
    for (const json& p : points)
      t.rows.push_back({escape(p.at("name").get<std::string>()), escape(p.at("kind").get<std::string>()),
                        cell(p.at("median_ms"), cli::fixedDigits(p.at("median_ms"), 2)),
                        cell(p.at("speedup_vs_llvmpipe"), cli::fixedDigits(p.at("speedup_vs_llvmpipe"), 2) + "x"),
                        cell(p.at("psnr_vs_llvmpipe_db"), psnrText(p.at("psnr_vs_llvmpipe_db"))),
                        cell(p.at("share_over1_vs_llvmpipe"), percent(p.at("share_over1_vs_llvmpipe"))),
                        cell(p.at("max_diff_vs_llvmpipe"), cli::sixDigits(p.at("max_diff_vs_llvmpipe"))),
                        cell(p.at("psnr_vs_precise_db"), psnrText(p.at("psnr_vs_precise_db"))),
                        escape(p.value("pareto", false) ? "*" : "")});
    out += t.html();
  }
  return out;
}

std::string sweepTables(const json& sweep, const std::string& idPrefix) {
  std::string out;
  if (sweep.contains("first_failure")) {
    Table first{idPrefix + "-first", "first failing value of " + sweep.at("param").get<std::string>(),
                {"side", "first failing value"}, {}};
    for (const auto& [side, value] : sweep.at("first_failure").items())
      first.rows.push_back({escape(side), value.is_null() ? escape("none") : cell(value, cli::sixDigits(value))});
    out += first.html();
  }
  Table points{idPrefix + "-points", "",
               {"value", "side", "identical", "PSNR (dB)", "> 1 step", "max step", "non-finite", "worst target",
                "worst target PSNR (dB)", "fails"},
               {}};
  for (const json& p : sweep.at("points"))
    points.rows.push_back({cell(p.at("value"), cli::sixDigits(p.at("value"))), escape(p.at("method").get<std::string>()),
                           escape(p.at("identical_to_llvmpipe").get<bool>() ? "yes" : "no"),
                           cell(p.at("psnr_vs_llvmpipe_db"), psnrText(p.at("psnr_vs_llvmpipe_db"))),
                           cell(p.at("share_over1_vs_llvmpipe"), percent(p.at("share_over1_vs_llvmpipe"))),
                           cell(p.at("max_diff_vs_llvmpipe"), cli::sixDigits(p.at("max_diff_vs_llvmpipe"))),
                           cell(p.at("nonfinite_pixels"), jsonText(p.at("nonfinite_pixels"))),
                           escape(jsonText(p.at("worst_target"))),
                           cell(p.at("worst_target_psnr_db"), psnrText(p.at("worst_target_psnr_db"))),
                           escape(p.at("fails").get<bool>() ? p.value("failure", std::string("fails")) : "")});
  out += details(escape("every point (" + std::to_string(points.rows.size()) + " rows)"), points.html());
  return out;
}

std::string sidecarTable(const json& sidecar, const std::string& id) {
  if (!sidecar.is_object()) return "<pre>" + escape(sidecar.dump(2)) + "</pre>";
  Table t{id, "", {"field", "value"}, {}};
  std::string nested;
  for (const auto& [key, value] : sidecar.items()) {
    if (value.is_structured()) {
      nested += details(escape(key), "<pre>" + escape(value.dump(2)) + "</pre>");
      continue;
    }
    t.rows.push_back({escape(key), value.is_number() ? cell(value, jsonText(value)) : escape(jsonText(value))});
  }
  return (t.rows.empty() ? std::string() : t.html()) + nested;
}

}  // namespace report
