// The command line with one more scene row: the shadow scene again, under the name
// `shadow-again`. The registry suite (tests/scenes/registry_test.cpp) runs it to see that
// `raster scenes`, every command and the bench/ runners take a new row with no other line
// changed.
#include "apps/command_line.h"
#include "scenes/registry.h"

int main(int argc, char** argv) {
  scenes::SceneEntry row = scenes::sceneEntry("shadow");
  row.name = "shadow-again";
  row.description = "the shadow scene under a second name (tests/registry/)";
  scenes::registerScene(std::move(row));
  return cli::run(argc, argv);
}
