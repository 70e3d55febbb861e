// `raster render` (render.h).
#include "apps/render/render.h"

#include <iostream>

#include "apps/common/sides.h"
#include "apps/views/view_render.h"
#include "io/image_io.h"
#include "io/target_dump.h"
#include "backends/backends.h"

namespace cli {

int runRender(const RenderArgs& args) {
  const Frame frame = validateFrame(args);
  if (args.backend != "raster" && args.backend != "gl")
    throw UsageError("--backend: '" + args.backend + "' is neither raster nor gl");
  if (!args.view.empty()) return runViewRender(args, frame);
  if (!args.pass.empty()) throw UsageError("--pass chooses the pass of a --view");
  if (args.backend == "gl") refuseOwnOptionsOnGl(frame, "--backend gl");
  const std::string out = args.out.empty() ? frame.scene + ".png" : args.out;
  checkOutputPng("--out", out);
  if (!args.dump.empty()) checkOutputFolder("--dump", args.dump);
  if (args.backend == "gl") scenes::checkGalliumEnvironment();

  const Side side = renderInProcess(frame, args.backend, /*finalOnly=*/args.dump.empty());
  // The dump's names are the scene's targets, known now: each checked before any file is
  // written, --out's included.
  if (!args.dump.empty()) checkOutputFolder("--dump", args.dump, compare::targetDumpFiles(side.targets));
  compare::writePng(out, side.targets.back().image);
  std::cout << "wrote " << out << std::endl;
  if (!args.dump.empty()) dumpTargets(args.dump, side.targets);
  return 0;
}

}  // namespace cli
