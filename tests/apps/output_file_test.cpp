// Every file the program writes goes through one writer (io/output_file.h): it never
// replaces anything but a regular file, writes whole or not at all, reports a full disk or
// a file-size limit as an error naming the path, and leaves no temporary file behind when a
// signal ends the process mid-write.
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <string>

#include "tests/apps/cli_test_helpers.h"

namespace {

using namespace cli_test;

// The folder holds exactly the named entries (no temporary or partial file).
void expectOnly(const fs::path& folder, std::initializer_list<std::string> names) {
  size_t count = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    ++count;
    bool expected = false;
    for (const std::string& name : names) expected = expected || entry.path().filename() == name;
    INFO("left in the folder: " << entry.path().filename());
    CHECK(expected);
  }
  CHECK(count == names.size());
}

const char* kSmallRender = "render shadow --size 64x48 --threads 1";

}  // namespace

TEST_SUITE("hostile") {
  TEST_CASE("output: a symbolic link, a FIFO or a device at the path is refused, not replaced") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    {
      std::ofstream(temp.path / "precious.txt") << "keep me";
      fs::create_symlink(temp.path / "precious.txt", cwd / "link.png");
      const RunResult r = runCli(cwd, std::string(kSmallRender) + " --out link.png");
      INFO(r.err);
      CHECK(r.status == 2);
      CHECK(r.err.find("symbolic link") != std::string::npos);
      CHECK(r.err.rfind("raster: --out: cannot write link.png: it is a symbolic link", 0) == 0);   // refused up front, before rendering
      CHECK(fs::is_symlink(cwd / "link.png"));
      CHECK(readText(temp.path / "precious.txt") == "keep me");
      fs::remove(cwd / "link.png");
    }
    {
      REQUIRE(mkfifo((cwd / "fifo.png").c_str(), 0644) == 0);
      const RunResult r = runShell(cwd, std::string("timeout 60 \"$RASTER\" ") + kSmallRender + " --out fifo.png");
      INFO(r.err);
      CHECK(r.status == 2);   // refused at once: never opened (a FIFO would block), never renamed over
      CHECK(r.err.find("FIFO") != std::string::npos);
      CHECK(fs::is_fifo(cwd / "fifo.png"));
      fs::remove(cwd / "fifo.png");
    }
    for (const char* device : {"/dev/null", "/dev/full"}) {
      const RunResult r = runCli(cwd, std::string(kSmallRender) + " --out " + device);
      INFO(device << ": " << r.err);
      CHECK(r.status == 2);
      CHECK(r.err.find("device") != std::string::npos);
    }
    // bench --json to /dev/full used to exit 0 with nothing written.
    const RunResult bench = runCli(cwd, "bench shadow --size 32x32 --frames 1 --warmup 0 --threads 1 --json /dev/full");
    CHECK(bench.status == 2);
    expectOnly(cwd, {});
  }

  TEST_CASE("output: a name longer than the file system allows is bad input") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    const RunResult r = runCli(cwd, std::string(kSmallRender) + " --out " + std::string(300, 'a') + ".png");
    CHECK(r.status == 2);
    CHECK(r.err.find("longer than") != std::string::npos);
    expectOnly(cwd, {});
  }

  // `ulimit -f` caps the file size, as a full disk would stop the write: with SIGXFSZ ignored
  // the write fails (EFBIG) and the program says so and exits 1; with its default action
  // the signal ends the program, whose handler first removes the temporary file.
  TEST_CASE("output: a write that fails or is cut short by SIGXFSZ leaves no file behind") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directory(cwd);
    const std::string render = "\"$RASTER\" render shadow --size 320x240 --threads 1 --out big.png";
    const RunResult failed = runShell(cwd, "trap '' XFSZ; ulimit -f 4; " + render);
    INFO(failed.err);
    CHECK(failed.status == 1);
    CHECK(failed.err.find("cannot write big.png") != std::string::npos);
    CHECK(failed.err.find("File too large") != std::string::npos);
    expectOnly(cwd, {});
    const RunResult killed = runShell(cwd, "ulimit -f 4; " + render);
    CHECK(killed.signal == SIGXFSZ);
    expectOnly(cwd, {});
  }

  // The writer holds its finished temporary file before the rename when asked (a test hook),
  // so the signal surely arrives while the file exists.
  TEST_CASE("output: SIGINT, SIGTERM or SIGHUP mid-write removes the temporary file") {
    for (const char* signal : {"INT", "TERM", "HUP"}) {
      TempFolder temp;
      const fs::path cwd = temp.path / "cwd";
      fs::create_directory(cwd);
      // set -m: job control, or bash would start the background job with SIGINT ignored.
      // (Appended piece by piece: GCC 12 reads a chain of operator+ on temporaries here as a
      // copy past a string's end, a false -Warray-bounds, depending on what else it inlines.)
      std::string script = "set -m\nRASTER_TEST_STALL_BEFORE_RENAME=20000 \"$RASTER\" ";
      script += kSmallRender;
      script += " --out out.png & pid=$!\n"
                "for i in $(seq 600); do ls .raster-*.tmp >/dev/null 2>&1 && break; sleep 0.05; done\n"
                "ls .raster-*.tmp >/dev/null 2>&1 || exit 90\n"
                "kill -";
      script += signal;
      script += " $pid; wait $pid";
      const RunResult r = runShell(cwd, script);
      INFO("SIG" << std::string(signal) << ": status " << r.status << " signal " << r.signal << " " << r.err);
      CHECK(r.status != 90);   // the temporary file was there to be removed
      CHECK(r.signal != 0);    // the signal ended the program (re-raised after the clean-up)
      expectOnly(cwd, {});
    }
  }
  // A report is made in a hidden folder beside DIR, and a softpipe side dumps into a folder
  // under TMPDIR: both were left behind when the run was interrupted. The signal comes once
  // the folder holds a file (the report's scratch folder; the child's first file, held by
  // the writer's stall); the whole job,
  // the child with it, gets it, as from Ctrl-C.
  TEST_CASE("output: SIGTERM or SIGINT mid-run removes the report's and the child's temporary folders") {
    const std::pair<const char*, const char*> runs[] = {
        {"report shadow --size 32x24 --pixels 0 --no-default-include --quiet --out r", ".r.report-*/.scratch"},
        {"compare shadow --size 32x24 --reference softpipe --quiet --out c", "tmp/raster-*/.raster-*.tmp"}};
    for (const auto& [command, inside] : runs)
      for (const char* signal : {"TERM", "INT"}) {
        TempFolder temp;
        const fs::path cwd = temp.path / "cwd";
        fs::create_directories(cwd / "tmp");
        std::string script = "set -m\nTMPDIR=$PWD/tmp RASTER_TEST_STALL_BEFORE_RENAME=20000 \"$RASTER\" ";
        script += command;
        script += " & pid=$!\nfor i in $(seq 600); do ls -d ";
        script += inside;
        script += " >/dev/null 2>&1 && break; sleep 0.05; done\nls -d ";
        script += inside;
        script += " >/dev/null 2>&1 || exit 90\nkill -";
        script += signal;
        script += " -$pid; wait $pid";
        const RunResult r = runShell(cwd, script);
        INFO(command << ", SIG" << signal << ": status " << r.status << " signal " << r.signal << " " << r.err);
        CHECK(r.status != 90);   // the folder was there to be removed
        expectOnly(cwd, {"tmp"});
        CHECK(fs::is_empty(cwd / "tmp"));
      }
  }

  // `kill PID` reaches the parent alone, not its job: the softpipe child it waits for, held
  // 20 s by the writer's stall, went on running after the parent had gone. The parent's
  // handler passes the signal on; the child is looked for by its parent's pid in /proc, and
  // its state read there.
  TEST_CASE("output: a signal to the parent alone ends the child process it waits for") {
    TempFolder temp;
    const fs::path cwd = temp.path / "cwd";
    fs::create_directories(cwd / "tmp");
    const RunResult r = runShell(
        cwd,
        "TMPDIR=$PWD/tmp RASTER_TEST_STALL_BEFORE_RENAME=20000 \"$RASTER\" compare shadow --size 32x24 "
        "--reference softpipe --quiet --out c & pid=$!\n"
        "for i in $(seq 600); do ls -d tmp/raster-*/.raster-*.tmp >/dev/null 2>&1 && break; sleep 0.05; done\n"
        "child=$(grep -l \"^PPid:[[:space:]]*$pid\\$\" /proc/[0-9]*/status 2>/dev/null | head -1 | cut -d/ -f3)\n"
        "[ -n \"$child\" ] || exit 90\n"
        "kill -TERM $pid; wait $pid\n"
        // Gone, or a zombie (ended; whether this machine's init reaps orphans soon is its own
        // affair): either way no longer running.
        "for i in $(seq 100); do grep -qs '^State:[[:space:]]*[RSDT]' /proc/$child/status || exit 0; sleep 0.05; done\n"
        "kill -KILL $child; exit 91");
    INFO("status " << r.status << " " << r.err);
    CHECK(r.status == 0);   // 90: no child found; 91: the child outlived its parent by 5 s
    expectOnly(cwd, {"tmp"});
    CHECK(fs::is_empty(cwd / "tmp"));
  }
}
