// raster: the command line (command_line.h). The commands are the records of commands.h;
// this makes a CLI11 subcommand of each, parses, runs the one chosen, and turns what it
// throws into the exit status. Options and their checks live with each command
// (apps/NAME/) and in apps/common/cli_options.h; everything is validated before rendering.
//
// Exit status: 0 success; 1 internal failure, a compare threshold exceeded or a soup seed
// that differs; 2 bad input.
#include "apps/command_line.h"

#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "apps/commands.h"
#include "apps/common/cli_options.h"
#include "io/output_file.h"
#include "io/utf8.h"
#include "scenes/scene.h"
#include "scenes/scene_params.h"

namespace cli {
namespace {

// One line, as the single error line demands, that a person can read: a word (a run without
// spaces: a value, a path) longer than kLongWord bytes, echoed from the command line, keeps
// its head and tail around how much was left out. Cuts fall between UTF-8 characters.
std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n') c = ' ';
  constexpr size_t kLongWord = 300, kHead = 120, kTail = 60;
  std::string shown;
  for (size_t start = 0; start < text.size();) {
    const size_t space = text.find(' ', start), end = space == std::string::npos ? text.size() : space;
    if (end - start <= kLongWord) {
      shown.append(text, start, end - start);
    } else {
      const size_t headEnd = compare::utf8CharacterStart(text, start + kHead);
      const size_t tailStart = compare::utf8CharacterStart(text, end - kTail);
      shown.append(text, start, headEnd - start);
      shown += "...[" + std::to_string(tailStart - headEnd) + " bytes not shown]...";
      shown.append(text, tailStart, end - tailStart);
    }
    if (end < text.size()) shown += ' ';
    start = end + 1;
  }
  return shown;
}

// Bad input: one line on stderr, exit status 2.
int refuse(const std::string& message) {
  std::cerr << "raster: " << oneLine(message) << std::endl;
  return 2;
}

// An option given an empty value (`--max-rmse ""`, `--out=`) is refused: CLI11 counts it as
// given but stores nothing, so the command would run as if it were left out (a compare
// threshold off, a whole sweep instead of its shard, the default file name).
void refuseEmptyValues(const CLI::App& command) {
  for (const CLI::Option* option : command.get_options()) {
    if (option->get_type_size_max() == 0) continue;   // a flag takes no value
    for (const std::string& value : option->results())
      if (value.empty())
        throw UsageError(option->get_name() + ": an empty value (give one, or leave the option out)");
  }
}

// A frame option given twice, as --set NAME=VALUE (or a sweep's --param NAME=RANGE) and as
// the command's own --NAME (scenes::isFrameOption: time, size, instances): neither silently
// wins. Other names (--set threads=2 beside --threads) are left to --set's own check.
void refuseParameterGivenTwice(const CLI::App& command) {
  for (const char* byName : {"--set", "--param"}) {
    const CLI::Option* option = command.get_option_no_throw(byName);
    if (option == nullptr) continue;
    for (const std::string& text : option->results()) {
      const std::string name = text.substr(0, text.find('='));
      if (!scenes::isFrameOption(name)) continue;
      const CLI::Option* rival = command.get_option_no_throw("--" + name);
      if (rival != nullptr && rival != option && rival->count() > 0)
        throw UsageError(std::string(byName) + " " + text + " and --" + name + " both give the " + name + "; give one");
    }
  }
}

}  // namespace

int run(int argc, char** argv) {
  CLI::App app{"A CPU software rasterizer for GL 3.3 scenes, checked against real OpenGL (OSMesa)", "raster"};
  app.require_subcommand(1);
  std::vector<std::pair<CLI::App*, CommandRun>> runs;
  for (const Command& command : commands()) {
    CLI::App* subcommand = app.add_subcommand(command.name, command.help);
    runs.emplace_back(subcommand, command.addOptions(*subcommand));
  }
  app.footer("Run 'raster COMMAND --help' for a command's options (" + commandList() + ").");

  // Parse: --help prints and exits 0; a malformed command line is bad input.
  if (argc > 1 && argv[1][0] != '-' && !findCommand(argv[1]))
    return refuse("'" + std::string(argv[1]) + "' is not a command (commands: " + commandList() + ")");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    return refuse(std::string(e.what()) + " (see raster --help)");
  }

  // Run: bad input and scene problems exit 2, anything else is an internal failure (1).
  try {
    for (const auto& [subcommand, runCommand] : runs)
      if (subcommand->parsed()) {
        refuseEmptyValues(*subcommand);
        refuseParameterGivenTwice(*subcommand);
        const int status = runCommand();
        // A listing or table that did not reach its file (a full disk: `raster scenes --json >
        // /dev/full`) is a failure, not a success.
        if (!std::cout.flush()) throw std::runtime_error("cannot write the standard output");
        return status;
      }
    return refuse("no command given (commands: " + commandList() + ")");   // require_subcommand(1) stops this first
  } catch (const UsageError& e) {
    return refuse(e.what());
  } catch (const scenes::SceneError& e) {
    return refuse(e.what());
  } catch (const compare::OutputPathError& e) {
    return refuse(e.what());
  } catch (const std::exception& e) {
    std::cerr << "raster: " << oneLine(e.what()) << std::endl;
    return 1;
  }
}

}  // namespace cli
