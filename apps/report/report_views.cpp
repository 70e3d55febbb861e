// The list of stage views as `raster render --view help` gives it (report_views.h).
#include "apps/report/report_views.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace report {

std::vector<std::string> parseViewNames(int status, const std::string& output) {
  const auto isName = [](const std::string& word) {
    static const std::vector<std::string> notNames = {"valid", "views", "view", "are", "and", "or", "known", "names", "help",
                                                      "unknown", "is", "not", "a", "the", "one", "of", "name", "raster"};
    if (word.empty() || !std::islower(static_cast<unsigned char>(word[0]))) return false;
    for (char c : word)
      if (!(std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '_'))
        return false;
    return std::find(notNames.begin(), notNames.end(), word) == notNames.end();
  };
  std::vector<std::string> names;
  const auto add = [&](const std::string& word) {
    if (isName(word) && std::find(names.begin(), names.end(), word) == names.end()) names.push_back(word);
  };
  if (status == 0) {
    std::istringstream lines(output);
    std::string line;
    while (std::getline(lines, line)) {
      std::istringstream words(line);
      std::string first;
      if (words >> first) add(first);
    }
    return names;
  }
  std::string line;
  {
    std::istringstream lines(output);
    for (std::string each; std::getline(lines, each);)
      if (!each.empty()) line = each;
  }
  const size_t open = line.rfind('('), colon = line.rfind(':');
  if (open != std::string::npos) line = line.substr(open + 1, line.find(')', open) - open - 1);
  else if (colon != std::string::npos) line = line.substr(colon + 1);
  const size_t colonInside = line.rfind(':');
  if (colonInside != std::string::npos) line = line.substr(colonInside + 1);
  for (char& c : line)
    if (c == ',' || c == '|' || c == ';') c = ' ';
  std::istringstream words(line);
  for (std::string word; words >> word;) add(word);
  return names;
}

}  // namespace report
