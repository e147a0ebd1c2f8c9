// PNG files of rendered frames, made in memory (issue 29: "a lighter path for PNG").
//
// Qt's PNG writer (libpng with zlib) leaves libpng's adaptive filter choice on: every row is
// filtered five ways and the smallest kept, more than half of the 55 ms a 1920x1080 dragon frame
// took to encode. Here every row takes one filter, "Up" (each byte less the one above it). A
// picture of flat tones, nearly all runs once filtered, is then compressed by the run coder
// (run_deflate.h): the toon dragon frame in 4 ms, files 2 % larger than libdeflate's; others by
// libdeflate at its level 7 (libpng with the same filter at zlib's default level: 24 ms a dragon
// frame, libdeflate 13 ms), no larger than libpng's adaptive ones on the dragon and on synthetic
// gradients. Which coder a picture takes is decided on a sample of its rows (png_encoder.cpp).
// The pixels are the same: PNG is lossless. The file is a signature, IHDR, one IDAT holding the
// zlib stream, and IEND (PNG 1.2, sections 5 and 11).
#pragma once

#include <QString>

#include <vector>

namespace celform::model {

/// Encodes width x height 8-bit pixels of 1 (grey), 3 (RGB) or 4 (RGBA, straight alpha) interleaved
/// channels, rows packed, as a PNG file's bytes into out (cleared first, its storage reused).
/// Returns the problem, empty on success.
QString encodePng(const unsigned char* pixels, int width, int height, int channels, std::vector<unsigned char>& out);

} // namespace celform::model
