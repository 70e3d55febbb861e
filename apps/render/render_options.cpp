// `raster render`'s options (render.h).
#include "apps/render/render.h"

namespace cli {

void addRenderOptions(CLI::App& command, RenderArgs& args) {
  addFrameOptions(command, args);
  command.add_option("--backend", args.backend, "raster (this pipeline) or gl (OSMesa)")
      ->type_name("raster|gl")->capture_default_str();
  command.add_option("--out", args.out, "PNG of the final image (default: SCENE.png)")
      ->type_name("FILE.png");
  command.add_option("--dump", args.dump,
                     "Folder for every target: NAME.png, and a lossless OpenEXR NAME.exr for depth/float targets")
      ->type_name("DIR");
  command.add_option("--view", args.view,
                     "Draw a stage view instead of the image, with its numbers in F.json beside --out F.png "
                     "(`raster views` lists them; docs/stage-views.md)")
      ->type_name("NAME");
  command.add_option("--pass", args.pass, "The pass a --view shows (a number from 0; default all, as a contact sheet)")
      ->type_name("N|all");
}

}  // namespace cli
