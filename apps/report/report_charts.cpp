// The tradeoff and sweep results in the report (report_charts.h).
#include "apps/report/report_charts.h"

#include <algorithm>

#include "apps/common/cli_options.h"
#include "apps/report/report_folder.h"
#include "apps/report/report_html.h"
#include "apps/report/report_results.h"
#include "io/output_file.h"

namespace report {

using nlohmann::json;

std::vector<ChartResult> findChartResults(const std::vector<std::string>& includes) {
  std::vector<ChartResult> found;
  for (const std::string& include : includes) {
    std::vector<fs::path> files;
    // A folder this user may not enter is passed over, and so is an entry of the right name
    // whose status cannot be read (a link into such a folder): neither holds a result. What
    // stops the walk itself (a folder removed meanwhile) is named, as bad input.
    std::error_code error;
    fs::recursive_directory_iterator entry(include, fs::directory_options::skip_permission_denied, error);
    for (; !error && entry != fs::recursive_directory_iterator(); entry.increment(error)) {
      const std::string name = entry->path().filename().string();
      std::error_code unreadable;
      if ((name == "tradeoff.json" || name == "sweep.json") && entry->is_regular_file(unreadable))
        files.push_back(entry->path());
    }
    if (error) throw cli::UsageError("--include: cannot search " + include + ": " + error.message());
    std::sort(files.begin(), files.end());   // the same order on every machine
    for (const fs::path& file : files) {
      const fs::path relative = fs::relative(file.parent_path(), include);
      const std::string label = (fs::path(include).filename().empty() ? fs::path(include).parent_path().filename()
                                                                     : fs::path(include).filename()) /
                                relative;
      found.push_back({file.stem().string(), file.parent_path(), fs::path(label).lexically_normal().string()});
    }
  }
  return found;
}

std::string chartSection(const ChartResult& result, const fs::path& reportFolder, int index, json& record) {
  const std::string base = "charts/" + std::to_string(index) + "-" + fileSafe(result.label);
  fs::create_directories(reportFolder / base);
  const std::string jsonFile = result.kind + ".json";
  // A result the user's --include folders hold that is not one is bad input (exit 2), as a
  // bad option is: the message names the file and what is wrong with it.
  const auto badResult = [&](const std::string& why) {
    return cli::UsageError("--include: " + (result.folder / jsonFile).string() + ": " + why);
  };
  std::string jsonText;
  json data;
  try {
    jsonText = readFile(result.folder / jsonFile);
    data = json::parse(jsonText);
  } catch (const json::exception& e) {
    throw badResult(std::string("not a ") + result.kind + " result: " + e.what());
  } catch (const std::runtime_error&) {
    throw badResult("cannot be read");
  }
  compare::writeOutputFile((reportFolder / base / jsonFile).string(), jsonText);
  std::string html = "<h3>" + escape(result.kind + ": " + result.label) + "</h3>\n";
  std::string image;
  for (const char* extension : {".png", ".svg"}) {
    const fs::path chart = result.folder / (result.kind + extension);
    if (!fs::is_regular_file(chart)) continue;
    image = base + "/" + result.kind + extension;
    compare::writeOutputFile((reportFolder / image).string(), readFile(chart));
    break;
  }
  if (!image.empty())
    html += "<figure class=\"chart\"><a href=\"" + escape(image) + "\"><img src=\"" + escape(image) + "\" alt=\"" +
            escape(result.kind + " chart") + "\"></a><figcaption>" + escape("from " + result.label + "; the data: ") +
            "<a href=\"" + escape(base + "/" + jsonFile) + "\">" + escape(jsonFile) + "</a></figcaption></figure>\n";
  else
    html += note("No chart (" + result.kind + ".png or .svg) beside " + jsonFile + " in " + result.label + ".");
  const std::string id = result.kind + "-" + std::to_string(index);
  try {
    html += result.kind == "tradeoff" ? tradeoffTables(data, id) : sweepTables(data, id);
  } catch (const json::exception& e) {
    throw badResult(std::string("not a ") + result.kind + " result: " + e.what());
  }
  record = {{"kind", result.kind}, {"source", result.label}, {"json", base + "/" + jsonFile}, {"image", image}, {"id", id}};
  return html;
}

}  // namespace report
