// Where `raster report` writes (report.h): nothing is half-written. The report is made in a
// temporary folder beside DIR and moved onto DIR when complete; a DIR that exists must be
// empty or an earlier report (it holds index.html and the report.json this command writes),
// which is then replaced whole, so a mistyped --out never replaces a user's folder.
#pragma once

#include <filesystem>
#include <string>

namespace report {

namespace fs = std::filesystem;

// Checks --out before anything renders: UsageError (exit 2) for a folder the report may not
// replace, or whose parent cannot be written.
void checkReportFolder(const std::string& out);

class ReportFolder {
 public:
  // Makes the temporary folder beside `out` (checked by checkReportFolder), with a scratch
  // folder inside it for the children's logs.
  explicit ReportFolder(const std::string& out);
  // Removes the temporary folder unless it was moved into place.
  ~ReportFolder();
  ReportFolder(const ReportFolder&) = delete;
  ReportFolder& operator=(const ReportFolder&) = delete;

  const fs::path& work() const { return work_; }         // the report being made
  const fs::path& scratch() const { return scratch_; }   // logs and probes, not part of the report
  const fs::path& target() const { return target_; }     // DIR

  // Removes the scratch folder and renames the report onto DIR (an earlier report there is
  // moved aside first, and removed after).
  void moveIntoPlace();

 private:
  std::string out_;
  fs::path target_, parent_, work_, scratch_;
  int slot_ = -1;   // work_ tracked for the signal handler (io/output_file.h)
  bool moved_ = false;
};

// A file's bytes; std::runtime_error naming it when it cannot be read.
std::string readFile(const fs::path& path);

}  // namespace report
