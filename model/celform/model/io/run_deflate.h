// A zlib stream (RFC 1950 around RFC 1951's deflate) made in one quick pass for data that is
// mostly repeats: the filtered scanlines of a frame of flat tones, where runs of zeros (a flat
// region less the row above it) are nearly all there is (issue 29: the writer's PNG).
//
// General compressors (libdeflate, zlib) look for a match at every byte through hash chains, and
// insert every byte of a match into their tables: about 10 ms for the 8.3 MB of a 1920x1080 RGBA
// frame at libdeflate's fastest useful levels, most of it spent on the runs. Here a match is
// looked for only where the last one ended, at three distances a picture repeats at (one byte,
// one pixel, one scanline) and at the last place the same four bytes began, and the matches and
// literals of up to 32768 tokens share one block of dynamic Huffman codes (RFC 1951, 3.2.7).
// Pictures with few runs (gradients, noise) compress much worse than a general compressor does;
// deflateRuns says so through its size limit, and the caller compresses them the general way.
#pragma once

#include <cstddef>
#include <vector>

namespace celform::model {

/// Appends to out a zlib stream of the size bytes at data (any size, empty included; a window of
/// 32 KB, adler-32 at its end, "fastest" in its header). period and scanline are distances at
/// which the data tends to repeat (a pixel's and a row's bytes; 0: none). Returns false, out as it
/// was, when the stream would be longer than limit bytes, or data is 4 GiB or longer.
bool deflateRuns(const unsigned char* data, std::size_t size, std::size_t period, std::size_t scanline,
    std::size_t limit, std::vector<unsigned char>& out);

} // namespace celform::model
