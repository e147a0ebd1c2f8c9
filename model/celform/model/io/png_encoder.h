// PNG files of rendered frames, written with libpng in memory (issue 29: "a lighter path for PNG").
//
// Qt's PNG writer leaves libpng's adaptive filter choice on: every row is filtered five ways and
// the smallest kept, more than half of the 55 ms a 1920x1080 dragon frame took to encode. One
// fixed filter, "Up" (each byte less the one above it), does about as well on rendered frames:
// the dragon frame in 24 ms and 3 % more bytes with toon shading, 38 ms (66 ms adaptive) and 0.3 %
// more with Gooch's gradients; test_png_encoder checks the sizes on synthetic pictures. The pixels
// are the same: PNG is lossless.
#pragma once

#include <QString>

#include <vector>

namespace celform::model {

/// Encodes width x height 8-bit pixels of 1 (grey), 3 (RGB) or 4 (RGBA, straight alpha) interleaved
/// channels, rows packed, as a PNG file's bytes into out (cleared first, its storage reused).
/// Returns the problem, empty on success.
QString encodePng(const unsigned char* pixels, int width, int height, int channels, std::vector<unsigned char>& out);

} // namespace celform::model
