// The table of `raster` commands (commands.h).
#include "apps/commands.h"

#include <memory>

#include "apps/bench/bench.h"
#include "apps/compare/compare.h"
#include "apps/lists/lists.h"
#include "apps/render/render.h"
#include "apps/report/report.h"
#include "apps/soup/soup.h"
#include "apps/sweep/sweep.h"
#include "apps/trace/trace.h"
#include "apps/tradeoff/tradeoff.h"

namespace cli {
namespace {

// A command with options: its Args live as long as its run, CLI11 fills them while parsing
// (addArgs binds each option to a field), and run reads them.
template <class Args, void (*addArgs)(CLI::App&, Args&), int (*run)(const Args&)>
CommandRun withArgs(CLI::App& command) {
  auto args = std::make_shared<Args>();
  addArgs(command, *args);
  return [args] { return run(*args); };
}

// A command without options.
template <int (*run)()>
CommandRun withoutArgs(CLI::App&) {
  return run;
}

}  // namespace

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"render", "Render one frame of a scene to PNG", withArgs<RenderArgs, addRenderOptions, runRender>},
      {"compare", "Render a scene with a test and a reference backend and compare every target",
       withArgs<CompareArgs, addCompareOptions, runCompare>},
      {"bench", "Time this pipeline against a GL driver, frames alternating", withArgs<BenchArgs, addBenchOptions, runBench>},
      {"tradeoff", "Race every method set against llvmpipe and softpipe; chart speed against accuracy",
       withArgs<TradeoffArgs, addTradeoffOptions, runTradeoff>},
      {"sweep",
       "Move one scene parameter toward where methods fail; score every method set and softpipe against llvmpipe",
       withArgs<SweepArgs, addSweepOptions, runSweep>},
      {"sweep-merge", "Join the shards of a sweep (raster sweep --shard K/N) into one",
       withArgs<SweepMergeArgs, addSweepMergeOptions, runSweepMerge>},
      {"report",
       "An HTML report: per scene and target ours, GL and the difference with metrics, stage views, "
       "pixel histories, tradeoff and sweep charts",
       withArgs<ReportArgs, addReportOptions, runReport>},
      {"soup", "Random triangle soups through this pipeline and llvmpipe; coverage and depth compared exactly",
       withArgs<SoupArgs, addSoupOptions, runSoup>},
      {"trace",
       "Pixel history: every fragment that reached one pixel, in every pass that made it, and why it is what it is",
       withArgs<TraceArgs, addTraceOptions, runTrace>},
      {"methods", "List the methods of each pipeline step, and the presets (--json: as one object)",
       withArgs<MethodsArgs, addMethodsOptions, listMethods>},
      {"params", "List a scene's parameters (--set NAME=VALUE), with range and meaning",
       withArgs<ParamsArgs, addParamsOptions, listParams>},
      {"scenes", "List the scenes, one a line (--json: every registry row)", withArgs<ScenesArgs, addScenesOptions, listScenes>},
      {"views", "List the stage views of render --view, one a line, with what each shows", withoutArgs<listViews>},
  };
  return table;
}

const Command* findCommand(const std::string& name) {
  for (const Command& command : commands())
    if (name == command.name) return &command;
  return nullptr;
}

std::string commandList() {
  std::string list;
  for (const Command& command : commands()) list += (list.empty() ? "" : ", ") + std::string(command.name);
  return list;
}

}  // namespace cli
