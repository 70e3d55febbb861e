// raster: the command-line program (apps/command_line.h).
#include "apps/command_line.h"

int main(int argc, char** argv) { return cli::run(argc, argv); }
