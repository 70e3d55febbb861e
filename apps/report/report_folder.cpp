// The report's folder (report_folder.h).
#include "apps/report/report_folder.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "apps/common/cli_options.h"
#include "io/output_file.h"

namespace report {
namespace {

// DIR as a folder name: "out/" is "out".
fs::path folderOf(const std::string& out) {
  fs::path folder = fs::path(out).lexically_normal();
  if (!folder.has_filename()) folder = folder.parent_path();
  return folder;
}

fs::path parentOf(const fs::path& folder) { return folder.has_parent_path() ? folder.parent_path() : fs::path("."); }

// Whether `folder` holds an earlier report: its index.html, and a report.json that this
// command wrote (its "made_by"). A file of that common name alone is not enough: another
// tool's report.json would have the user's folder replaced whole.
bool holdsEarlierReport(const fs::path& folder) {
  std::error_code error;
  const fs::path record = folder / "report.json";
  if (!fs::is_regular_file(record, error) || !fs::is_regular_file(folder / "index.html", error)) return false;
  const auto size = fs::file_size(record, error);
  if (error || size > (64u << 20)) return false;   // far above any report's record
  std::ifstream in(record, std::ios::binary);
  const nlohmann::json parsed = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  return parsed.is_object() && parsed.value("made_by", nlohmann::json()) == "raster report";
}

}  // namespace

void checkReportFolder(const std::string& out) {
  using cli::UsageError;
  cli::checkOutputFolder("--out", out);
  const fs::path folder = folderOf(out);
  if (folder.empty() || folder == "." || folder == "..")
    throw UsageError("--out: '" + out + "' must name a folder of its own (it is replaced as a whole)");
  struct stat info {};
  if (lstat(folder.c_str(), &info) == 0) {
    if (S_ISLNK(info.st_mode)) throw UsageError("--out: " + out + " is a symbolic link; name the folder itself");
    if (!S_ISDIR(info.st_mode)) throw UsageError("--out: " + out + " exists and is not a folder");
    std::error_code error;
    if (!fs::is_empty(folder, error) && !holdsEarlierReport(folder))
      throw UsageError("--out: " + out + " is not empty and holds no earlier report (an index.html and the report.json "
                       "raster report writes); name a new folder");
  }
  // The report is made beside DIR and renamed onto it: the parent must be writable too.
  const fs::path parent = parentOf(folder);
  if (!cli::writableFolder(parent))
    throw UsageError("--out: cannot write into " + parent.string() + " (the report is made beside " + out + ")");
}

ReportFolder::ReportFolder(const std::string& out) : out_(out), target_(folderOf(out)), parent_(parentOf(target_)) {
  std::string pattern = (parent_ / ("." + target_.filename().string() + ".report-XXXXXX")).string();
  if (!mkdtemp(pattern.data()))
    throw std::runtime_error("cannot create a folder beside " + out + ": " + std::strerror(errno));
  work_ = pattern;
  slot_ = compare::trackTemporaryFolder(work_.string());   // removed if a signal ends the run
  scratch_ = work_ / ".scratch";
  fs::create_directory(scratch_);
}

ReportFolder::~ReportFolder() {
  compare::untrackTemporaryFolder(slot_);
  std::error_code ignored;
  if (!moved_) fs::remove_all(work_, ignored);
}

void ReportFolder::moveIntoPlace() {
  compare::untrackTemporaryFolder(slot_);   // from here it becomes DIR: a signal must not remove it
  slot_ = -1;
  fs::remove_all(scratch_);
  chmod(work_.c_str(), 0755);   // mkdtemp made it private; a report is for reading
  std::error_code error;
  if (fs::exists(target_, error) && !fs::is_empty(target_, error)) {
    std::string aside = (parent_ / ("." + target_.filename().string() + ".old-XXXXXX")).string();
    if (!mkdtemp(aside.data()) || rename(target_.c_str(), aside.c_str()) != 0)
      throw std::runtime_error("cannot replace " + out_ + ": " + std::strerror(errno));
    if (rename(work_.c_str(), target_.c_str()) != 0) {
      const int why = errno;
      rename(aside.c_str(), target_.c_str());
      throw std::runtime_error("cannot replace " + out_ + ": " + std::strerror(why));
    }
    fs::remove_all(aside, error);
  } else if (rename(work_.c_str(), target_.c_str()) != 0) {
    throw std::runtime_error("cannot write " + out_ + ": " + std::strerror(errno));
  }
  moved_ = true;
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

}  // namespace report
