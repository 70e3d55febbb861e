// Whether an image file's bytes are whole, before stb_image decodes them (assets.cpp).
//
// stb_image 2.27 says no more than "expected marker" for a truncated JPEG, and never returns
// on a truncated run-length Radiance HDR (measured: the cannon .hdr cut in half spins
// forever). So each format's structure is walked first: JPEG markers up to EOI, PNG chunks
// up to IEND, and every run-length scanline of an HDR, exactly as the decoder will consume
// them. Each walk returns "" when the file is complete, else one line saying what is wrong
// and where.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace scenes {

// A file's bytes, read whole into a string, as the decoders and the walks below take them.
inline const uint8_t* bytesOf(const std::string& data) { return reinterpret_cast<const uint8_t*>(data.data()); }

// The format's signature at the start of the bytes.
bool isJpeg(const std::string& data);
bool isPng(const std::string& data);

// Walks the JPEG's segments and scans up to its end-of-image marker; *w and *h get the
// first frame header's size (left alone if there is none).
std::string jpegStructureProblem(const std::string& data, long* w, long* h);
// Walks the PNG's chunks up to IEND; *w and *h get the IHDR size when it comes first.
std::string pngStructureProblem(const std::string& data, long* w, long* h);
// Checks a Radiance HDR's pixel data, from byte `pos` (after the resolution line), for a
// w x h image.
std::string hdrDataProblem(const std::string& data, size_t pos, int w, int h);

}  // namespace scenes
