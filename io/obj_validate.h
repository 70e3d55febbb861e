// Checks an OBJ file line by line before tinyobjloader reads it, so that every problem is an
// error naming the file, the line and what is wrong, and tinyobjloader only ever sees input
// it handles right. In particular it stores a face's corner count in an unsigned char: a
// face of 256 or more corners would wrap around and make it skip its index checks.
//
// Accepted: "v x y z [w]", "vt u v [w]", "vn x y z", "f" with 3 to kMaxObjFaceCorners corners
// "v", "v/vt", "v//vn" or "v/vt/vn" (indices from 1, or negative: relative to the last
// element defined), comments, blank lines and the grouping keywords tinyobjloader ignores
// for meshes (o, g, s, usemtl, mtllib, l, p). Refused, with file:line: a number that is not
// a finite float, a coordinate beyond kMaxObjCoordinate, a wrong count of numbers, a face
// of fewer than 3 or more than kMaxObjFaceCorners corners, an index of 0 or pointing past the
// elements the file defines, an unknown keyword, and a file whose last line has no end of
// line (it was cut short: OBJ has no end marker, and that is the only trace a cut leaves
// when it falls inside a line).
#pragma once

#include <string>
#include <string_view>

namespace scenes {

// tinyobjloader's per-face count is an unsigned char.
constexpr int kMaxObjFaceCorners = 255;
// Past this, upload_cat's normalisation (height scaled to 2.2) leaves the rest of a mesh
// within float rounding of a point: 1e6 keeps 1e-7 relative detail of a 2.2-unit model.
constexpr double kMaxObjCoordinate = 1.0e6;

// Throws SceneError("asset PATH:LINE: PROBLEM") for the first problem found.
void validateObj(const std::string& path, std::string_view text);

}  // namespace scenes
