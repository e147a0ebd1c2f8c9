// EXR files of rendered frames, made in memory (issue 29: "find why EXR costs 1.5 times PNG").
//
// OpenEXR's core library (OpenEXRCore) writes the container: the header, the chunk offset table
// and the chunks in order. The chunks are compressed here, as OpenEXR's ZIP method defines them
// (the bytes of a block split into even and odd halves, each byte less the one before it, the
// result a zlib stream), but by libdeflate instead of zlib: an every-pass frame of the dragon at
// 1920x1080 (12 float channels, 95 MB) compressed in about two thirds of zlib's time at its
// fastest level, and into smaller chunks (docs/farm.md has the figures). The channels are read
// straight from where the render left them, scanline by scanline, so that no interleaved copy
// of the 95 MB is made first and none is converted again by a general-purpose writer.
//
// The files are standard scanline EXRs: 32-bit float channels sorted by name, ZIP over single
// scanlines ("zips", as before and as Nuke writes by default), increasing Y, no time stamp. A
// block whose compressed form would not be smaller is stored as it is, as OpenEXR does.
#pragma once

#include <QString>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace celform::model {

/// Where one channel's samples are: the sample of pixel (x, y) is element (y * width + x) * stride
/// of first, read as kind says.
struct ExrChannelSource {
    enum class Kind {
        Float, ///< floats as they are
        FiniteFloat, ///< floats, infinities and NaNs written as 0 (a depth pass's background)
        Int32, ///< 32-bit integers written as floats (ids)
    };
    std::string name;
    const void* first = nullptr;
    std::size_t stride = 1;
    Kind kind = Kind::Float;
};

/// Encodes width x height pixels of channels as an EXR file's bytes into out (cleared first, its
/// storage reused). Returns the problem, empty on success.
QString encodeExr(
    int width, int height, const std::vector<ExrChannelSource>& channels, std::vector<unsigned char>& out);

} // namespace celform::model
