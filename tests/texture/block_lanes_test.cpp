// BlockLanes (raster/simd/lane_layout.h), the sixteen lanes of a shaded 4x4 block as the
// samplers' 16-lane block paths read them, against where the pipeline puts each lane's pixel:
// LaneLayout's offsets for the block's two 8-lane groups, in an offscreen target and in a
// window-system buffer. The samplers' lane tables are built from BlockLanes, so a change to
// the layout that it did not follow would send those paths' texels to the wrong lanes.
#include <doctest/doctest.h>

#include <initializer_list>

#include "raster/simd/lanes.h"
#include "raster/simd/lane_layout.h"

TEST_SUITE("texture") {
  TEST_CASE("BlockLanes: each lane's column and row are its pixel's in the block, in GL's row order") {
    using raster::BlockLanes;
    for (const bool flipY : {false, true}) {
      CAPTURE(flipY);
      const raster::LaneLayout<raster::simd::Lanes<8>> layout(flipY, 0);
      bool seen[4][4] = {};
      for (int lane = 0; lane < BlockLanes::kCount; ++lane) {
        CAPTURE(lane);
        const int group = lane / 8, i = lane % 8;
        const int memoryColumn = layout.originX(group) + layout.dx[i], memoryRow = layout.originY(group) + layout.dy[i];
        CHECK(BlockLanes::column(lane) == memoryColumn);
        // Texel rows count upward: a window-system buffer stores its top row first.
        CHECK(BlockLanes::row(lane, flipY) == (flipY ? 3 - memoryRow : memoryRow));
        const int column = BlockLanes::column(lane), row = BlockLanes::row(lane, flipY);
        REQUIRE((column >= 0 && column < 4 && row >= 0 && row < 4));
        CHECK_FALSE(seen[row][column]);   // one lane a pixel
        seen[row][column] = true;
        CHECK(BlockLanes::at(column, row, flipY) == lane);
      }
    }
  }
}
