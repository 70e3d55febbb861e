// Stage views: `raster render SCENE --view NAME [--pass N] --out F.png`, a picture of where a
// frame's work goes, with its legend drawn in, and its numbers in the sidecar F.json. The
// views are the records of stage_views.h (`raster views` lists them).
//
// The count views show GL's semantics: every fragment in API order, quad by quad, as
// llvmpipe shades them (tile/inspect_tile.h), not the fragments this pipeline's fast paths
// skip (visibility first, covered tiles) without changing a byte. tile-cost times the
// pipeline's own path instead, fast paths included: it is what a frame costs here, and it
// varies from run to run. Every view leaves the rendered image's bytes as they are.
//
// By default the PNG is a contact sheet of every pass of the frame (each scaled to fit one
// cell, all on one colour scale); --pass N shows pass N alone at its own size.
#pragma once

#include <string>

#include "apps/common/cli_options.h"
#include "apps/render/render.h"

namespace cli {

// `raster render --view`: renders the frame with the view's recorder, writes the view's PNG
// and sidecar JSON (and with --dump every target). UsageError (exit 2) for an unknown view
// (also "help": the message lists the names), a --pass the frame does not have, or --backend
// gl; nothing is written then.
int runViewRender(const RenderArgs& args, const Frame& frame);

// F.png -> F.json; any other name gets ".json" appended.
std::string sidecarPath(const std::string& pngPath);

}  // namespace cli
