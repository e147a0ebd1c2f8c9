#include "celform/model/io/run_deflate.h"

#include <libdeflate.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>

namespace celform::model {
namespace {

constexpr std::size_t kWindow = 32768; // RFC 1951: distances 1 to 32768
constexpr std::size_t kMaxMatch = 258;
/// The shortest match taken: a 3-byte match costs about as many bits as three literals of a
/// picture's skewed alphabet.
constexpr std::size_t kMinMatch = 4;
/// A match at one of the picture's distances at least this long is not bettered through the hash.
constexpr std::size_t kGoodMatch = 32;
constexpr std::size_t kBlockTokens = 32768;
constexpr int kHashBits = 15;
constexpr int kLitLenSymbols = 286; // 0-255 literals, 256 end of block, 257-285 lengths
constexpr int kDistSymbols = 30;
constexpr int kCodeLengthSymbols = 19;
constexpr int kEndOfBlock = 256;

// RFC 1951, 3.2.5: the lengths and distances each code stands for.
constexpr std::array<std::uint16_t, 29> kLengthBase = {
    3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr std::array<std::uint8_t, 29> kLengthExtra
    = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr std::array<std::uint16_t, 30> kDistBase = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257,
    385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
constexpr std::array<std::uint8_t, 30> kDistExtra
    = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
// RFC 1951, 3.2.7: the order the code length code's lengths are stored in.
constexpr std::array<std::uint8_t, 19> kCodeLengthOrder
    = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};

/// Symbol of every length (3-258) and of every distance (through distance - 1 below 256, else
/// (distance - 1) >> 7 past 256), computed once.
struct Codes {
    std::array<std::uint8_t, kMaxMatch + 1> lengthCode{}; // index into kLengthBase
    std::array<std::uint8_t, 512> distCode{};

    Codes()
    {
        for (int c = 0; c < 29; ++c)
            for (int l = kLengthBase[std::size_t(c)]; l <= int(kMaxMatch); ++l)
                lengthCode[std::size_t(l)] = std::uint8_t(c); // later codes overwrite from their base on
        for (int c = 0; c < 30; ++c) {
            const int first = kDistBase[std::size_t(c)] - 1;
            const int last = first + (1 << kDistExtra[std::size_t(c)]) - 1;
            for (int d = first; d <= last; ++d) {
                if (d < 256)
                    distCode[std::size_t(d)] = std::uint8_t(c);
                else
                    distCode[std::size_t(256 + (d >> 7))] = std::uint8_t(c);
            }
        }
    }
    [[nodiscard]] int distanceSymbol(std::uint32_t distanceLess1) const
    {
        return distanceLess1 < 256 ? distCode[distanceLess1] : distCode[256 + (distanceLess1 >> 7)];
    }
};

const Codes& codes()
{
    static const Codes c;
    return c;
}

/// A token: a literal byte (below 256), or a match, (length << 16) | (distance - 1).
using Token = std::uint32_t;
constexpr Token kMatchFlag = Token(1) << 16; // every match token is at least 3 << 16

inline std::size_t matchLength(const unsigned char* a, const unsigned char* b, std::size_t most)
{
    std::size_t n = 0;
    while (n + 8 <= most) {
        std::uint64_t x, y;
        std::memcpy(&x, a + n, 8);
        std::memcpy(&y, b + n, 8);
        const std::uint64_t differ = x ^ y;
        if (differ != 0)
            return n + std::size_t(__builtin_ctzll(differ) >> 3); // little-endian: the first byte is lowest
        n += 8;
    }
    while (n < most && a[n] == b[n])
        ++n;
    return n;
}

/// Code lengths of at most limit bits for n symbols of the given frequencies (Huffman's, then
/// made to fit the limit by the usual lengthening of the deepest codes, as zlib and miniz do).
/// Every code made is complete: with fewer than two symbols used, symbols 0 and 1 make up two.
void codeLengths(const std::uint32_t* freq, int n, int limit, std::uint8_t* lengths)
{
    std::fill(lengths, lengths + n, std::uint8_t(0));
    std::array<int, kLitLenSymbols> used{};
    int count = 0;
    for (int s = 0; s < n; ++s)
        if (freq[s] > 0)
            used[std::size_t(count++)] = s;
    if (count < 2) {
        // One symbol or none: a one-bit code of two symbols, the one used and another (a decoder
        // takes the incomplete code of a single symbol badly).
        const int one = count == 1 ? used[0] : 0;
        lengths[one] = 1;
        lengths[one == 0 ? 1 : 0] = 1;
        return;
    }
    // Symbols by increasing frequency (ties by symbol: the same lengths for the same data).
    std::sort(used.begin(), used.begin() + count,
        [&](int a, int b) { return freq[a] != freq[b] ? freq[a] < freq[b] : a < b; });
    // Huffman's tree with two queues: the leaves in order, and the joined nodes, which come out in
    // order of weight too. Node k < count is leaf used[k]; node count + j is the j-th join.
    std::array<std::uint64_t, 2 * kLitLenSymbols> weight{};
    std::array<int, 2 * kLitLenSymbols> parent{};
    for (int k = 0; k < count; ++k)
        weight[std::size_t(k)] = freq[used[std::size_t(k)]];
    int leaf = 0, joined = count, made = count;
    auto take = [&]() {
        if (leaf < count && (joined >= made || weight[std::size_t(leaf)] <= weight[std::size_t(joined)]))
            return leaf++;
        return joined++;
    };
    while (made < 2 * count - 1) {
        const int a = take();
        const int b = take();
        weight[std::size_t(made)] = weight[std::size_t(a)] + weight[std::size_t(b)];
        parent[std::size_t(a)] = parent[std::size_t(b)] = made;
        ++made;
    }
    // Depths, root first (a node's parent comes after it).
    std::array<int, 2 * kLitLenSymbols> depth{};
    depth[std::size_t(made - 1)] = 0;
    for (int k = made - 2; k >= 0; --k)
        depth[std::size_t(k)] = depth[std::size_t(parent[std::size_t(k)])] + 1;
    // How many codes of each length, those beyond the limit cut to it; then, while the lengths
    // over-fill the code space (Kraft), one code at the limit goes and a shorter one splits in two.
    std::array<int, 64> perLength{};
    for (int k = 0; k < count; ++k)
        ++perLength[std::size_t(std::min(depth[std::size_t(k)], limit))];
    std::uint64_t space = 0;
    for (int l = 1; l <= limit; ++l)
        space += std::uint64_t(perLength[std::size_t(l)]) << (limit - l);
    while (space > (std::uint64_t(1) << limit)) {
        --perLength[std::size_t(limit)];
        for (int l = limit - 1; l > 0; --l)
            if (perLength[std::size_t(l)] > 0) {
                --perLength[std::size_t(l)];
                perLength[std::size_t(l + 1)] += 2;
                break;
            }
        --space;
    }
    // The shortest codes to the most frequent symbols.
    int k = count - 1;
    for (int l = 1; l <= limit; ++l)
        for (int c = 0; c < perLength[std::size_t(l)]; ++c)
            lengths[used[std::size_t(k--)]] = std::uint8_t(l);
}

/// Canonical codes of the lengths (RFC 1951, 3.2.2), bit-reversed: deflate sends codes from their
/// first (most significant) bit, into the low end of its bytes.
void canonicalCodes(const std::uint8_t* lengths, int n, std::uint16_t* out)
{
    std::array<int, 16> count{};
    for (int s = 0; s < n; ++s)
        ++count[lengths[s]];
    count[0] = 0;
    std::array<int, 16> next{};
    int code = 0;
    for (int l = 1; l < 16; ++l) {
        code = (code + count[std::size_t(l - 1)]) << 1;
        next[std::size_t(l)] = code;
    }
    for (int s = 0; s < n; ++s) {
        const int l = lengths[s];
        if (l == 0) {
            out[s] = 0;
            continue;
        }
        unsigned c = unsigned(next[std::size_t(l)]++), reversed = 0;
        for (int b = 0; b < l; ++b, c >>= 1)
            reversed = (reversed << 1) | (c & 1u);
        out[s] = std::uint16_t(reversed);
    }
}

/// Bits into bytes, the first bit lowest (RFC 1951, 3.1.1), into room the caller has made.
class BitWriter {
public:
    explicit BitWriter(unsigned char* at)
        : m_at(at)
    { }
    void put(std::uint32_t bits, int count) // count <= 32
    {
        m_buffer |= std::uint64_t(bits) << m_count;
        m_count += count;
        if (m_count >= 32) {
            const auto word = std::uint32_t(m_buffer);
            std::memcpy(m_at, &word, 4); // little-endian
            m_at += 4;
            m_buffer >>= 32;
            m_count -= 32;
        }
    }
    /// Writes what is left, padded to a whole byte; returns the end.
    unsigned char* finish()
    {
        while (m_count > 0) {
            *m_at++ = static_cast<unsigned char>(m_buffer);
            m_buffer >>= 8;
            m_count -= 8;
        }
        m_count = 0;
        return m_at;
    }

private:
    unsigned char* m_at;
    std::uint64_t m_buffer = 0;
    int m_count = 0;
};

/// One block's codes: what the tokens need, and the header describing them.
struct BlockCodes {
    std::array<std::uint32_t, kLitLenSymbols> litFreq{};
    std::array<std::uint32_t, kDistSymbols> distFreq{};
    std::array<std::uint8_t, kLitLenSymbols + kDistSymbols> lengths{}; // literal/length, then distance
    std::array<std::uint16_t, kLitLenSymbols> litCode{};
    std::array<std::uint16_t, kDistSymbols> distCode{};
    int hlit = 257, hdist = 1, hclen = 4;
    // The lengths run-length coded (RFC 1951, 3.2.7): symbol, extra bits value.
    std::array<std::uint8_t, kLitLenSymbols + kDistSymbols> clSymbol{};
    std::array<std::uint8_t, kLitLenSymbols + kDistSymbols> clExtra{};
    int clCount = 0;
    std::array<std::uint8_t, kCodeLengthSymbols> clLength{};
    std::array<std::uint16_t, kCodeLengthSymbols> clCode{};
    std::uint64_t bits = 0; // the whole block's

    void make(const Token* tokens, std::size_t count)
    {
        const Codes& c = codes();
        litFreq.fill(0);
        distFreq.fill(0);
        for (std::size_t t = 0; t < count; ++t) {
            const Token token = tokens[t];
            if (token < kMatchFlag) {
                ++litFreq[token];
            } else {
                ++litFreq[257 + std::size_t(c.lengthCode[token >> 16])];
                ++distFreq[std::size_t(c.distanceSymbol(token & 0xffffu))];
            }
        }
        litFreq[kEndOfBlock] = 1;
        std::uint8_t* litLengths = lengths.data();
        std::uint8_t* distLengths = lengths.data() + kLitLenSymbols;
        codeLengths(litFreq.data(), kLitLenSymbols, 15, litLengths);
        codeLengths(distFreq.data(), kDistSymbols, 15, distLengths);
        canonicalCodes(litLengths, kLitLenSymbols, litCode.data());
        canonicalCodes(distLengths, kDistSymbols, distCode.data());
        hlit = kLitLenSymbols;
        while (hlit > 257 && litLengths[hlit - 1] == 0)
            --hlit;
        hdist = kDistSymbols;
        while (hdist > 1 && distLengths[hdist - 1] == 0)
            --hdist;
        // The lengths in sequence, literal/length codes then distance codes, run-length coded.
        std::array<std::uint8_t, kLitLenSymbols + kDistSymbols> sequence{};
        std::copy(litLengths, litLengths + hlit, sequence.begin());
        std::copy(distLengths, distLengths + hdist, sequence.begin() + hlit);
        const int total = hlit + hdist;
        std::array<std::uint32_t, kCodeLengthSymbols> clFreq{};
        clCount = 0;
        auto addLength = [&](int symbol, int extra) {
            clSymbol[std::size_t(clCount)] = std::uint8_t(symbol);
            clExtra[std::size_t(clCount)] = std::uint8_t(extra);
            ++clCount;
            ++clFreq[std::size_t(symbol)];
        };
        for (int i = 0; i < total;) {
            const int value = sequence[std::size_t(i)];
            int run = 1;
            while (i + run < total && sequence[std::size_t(i + run)] == value)
                ++run;
            i += run;
            if (value == 0) {
                while (run >= 11) {
                    const int r = std::min(run, 138);
                    addLength(18, r - 11);
                    run -= r;
                }
                if (run >= 3) {
                    addLength(17, run - 3);
                    run = 0;
                }
            } else {
                addLength(value, 0);
                --run;
                while (run >= 3) {
                    const int r = std::min(run, 6);
                    addLength(16, r - 3);
                    run -= r;
                }
            }
            for (; run > 0; --run)
                addLength(value, 0);
        }
        codeLengths(clFreq.data(), kCodeLengthSymbols, 7, clLength.data());
        canonicalCodes(clLength.data(), kCodeLengthSymbols, clCode.data());
        hclen = kCodeLengthSymbols;
        while (hclen > 4 && clLength[kCodeLengthOrder[std::size_t(hclen - 1)]] == 0)
            --hclen;
        // The block's exact size, to keep within the caller's limit before writing it.
        bits = 3 + 5 + 5 + 4 + 3 * std::uint64_t(hclen);
        static constexpr std::array<int, 3> kRepeatExtra = {2, 3, 7};
        for (int k = 0; k < clCount; ++k) {
            const int s = clSymbol[std::size_t(k)];
            bits += clLength[std::size_t(s)] + (s >= 16 ? kRepeatExtra[std::size_t(s - 16)] : 0);
        }
        for (int s = 0; s < kLitLenSymbols; ++s)
            bits += std::uint64_t(litFreq[std::size_t(s)])
                * (litLengths[s] + (s >= 257 ? kLengthExtra[std::size_t(s - 257)] : 0));
        for (int s = 0; s < kDistSymbols; ++s)
            bits += std::uint64_t(distFreq[std::size_t(s)]) * (distLengths[s] + kDistExtra[std::size_t(s)]);
    }

    void write(BitWriter& w, const Token* tokens, std::size_t count, bool last) const
    {
        const Codes& c = codes();
        w.put(last ? 1u : 0u, 1);
        w.put(2u, 2); // dynamic Huffman codes
        w.put(std::uint32_t(hlit - 257), 5);
        w.put(std::uint32_t(hdist - 1), 5);
        w.put(std::uint32_t(hclen - 4), 4);
        for (int k = 0; k < hclen; ++k)
            w.put(clLength[kCodeLengthOrder[std::size_t(k)]], 3);
        static constexpr std::array<int, 3> kRepeatExtra = {2, 3, 7};
        for (int k = 0; k < clCount; ++k) {
            const int s = clSymbol[std::size_t(k)];
            w.put(clCode[std::size_t(s)], clLength[std::size_t(s)]);
            if (s >= 16)
                w.put(clExtra[std::size_t(k)], kRepeatExtra[std::size_t(s - 16)]);
        }
        const std::uint8_t* litLengths = lengths.data();
        const std::uint8_t* distLengths = lengths.data() + kLitLenSymbols;
        for (std::size_t t = 0; t < count; ++t) {
            const Token token = tokens[t];
            if (token < kMatchFlag) {
                w.put(litCode[token], litLengths[token]);
                continue;
            }
            const std::uint32_t length = token >> 16;
            const int lc = c.lengthCode[length];
            w.put(litCode[std::size_t(257 + lc)], litLengths[257 + lc]);
            w.put(length - kLengthBase[std::size_t(lc)], kLengthExtra[std::size_t(lc)]);
            const std::uint32_t distanceLess1 = token & 0xffffu;
            const int dc = c.distanceSymbol(distanceLess1);
            w.put(distCode[std::size_t(dc)], distLengths[dc]);
            w.put(distanceLess1 + 1 - kDistBase[std::size_t(dc)], kDistExtra[std::size_t(dc)]);
        }
        w.put(litCode[kEndOfBlock], litLengths[kEndOfBlock]);
    }
};

/// The longest match at a position among the picture's distances and the last place the same
/// four bytes began (a hash of them), within the window; shorter than kMinMatch: none.
class Search {
public:
    Search(const unsigned char* data, std::size_t size, std::size_t period, std::size_t scanline, std::uint32_t* table)
        : m_data(data)
        , m_size(size)
        , m_table(table)
    {
        for (const std::size_t d : {std::size_t(1), period, scanline})
            if (d > 0 && d <= kWindow
                && std::find(m_distances.begin(), m_distances.begin() + m_count, d) == m_distances.begin() + m_count)
                m_distances[std::size_t(m_count++)] = d;
    }

    /// The match's length at i (0 when under kMinMatch) and its distance; remember: whether i
    /// becomes the hash's last place of its four bytes.
    std::size_t at(std::size_t i, std::size_t& distance, bool remember)
    {
        const std::size_t most = std::min(kMaxMatch, m_size - i);
        if (most < kMinMatch)
            return 0;
        std::size_t best = 0;
        for (int k = 0; k < m_count && best < most; ++k) {
            const std::size_t d = m_distances[std::size_t(k)];
            if (d > i)
                continue;
            const std::size_t l = matchLength(m_data + i, m_data + i - d, most);
            if (l > best) {
                best = l;
                distance = d;
            }
        }
        if (best < kGoodMatch) {
            std::uint32_t key;
            std::memcpy(&key, m_data + i, 4);
            const std::uint32_t slot = (key * 2654435761u) >> (32 - kHashBits); // Knuth's multiplicative hash
            const std::size_t seen = m_table[slot]; // position + 1; 0: none
            if (remember)
                m_table[slot] = std::uint32_t(i + 1);
            if (seen > 0 && seen <= i && i + 1 - seen <= kWindow) {
                const std::size_t d = i + 1 - seen;
                const std::size_t l = matchLength(m_data + i, m_data + i - d, most);
                if (l > best) {
                    best = l;
                    distance = d;
                }
            }
        }
        return best >= kMinMatch ? best : 0;
    }

private:
    const unsigned char* m_data;
    std::size_t m_size;
    std::uint32_t* m_table;
    std::array<std::size_t, 3> m_distances{};
    int m_count = 0;
};

/// Per thread, reused from call to call: the tokens of a block, the hash table, the block's codes.
struct Scratch {
    std::vector<Token> tokens;
    std::vector<std::uint32_t> table; // position + 1 of the last four bytes of each hash; 0: none
    BlockCodes block;
};

} // namespace

bool deflateRuns(const unsigned char* data, std::size_t size, std::size_t period, std::size_t scanline,
    std::size_t limit, std::vector<unsigned char>& out)
{
    if (size >= std::numeric_limits<std::uint32_t>::max() || (size > 0 && !data))
        return false;
    thread_local Scratch scratch;
    scratch.tokens.resize(kBlockTokens);
    scratch.table.assign(std::size_t(1) << kHashBits, 0);
    Token* tokens = scratch.tokens.data();

    Search search(data, size, period, scanline, scratch.table.data());

    const std::size_t start = out.size();
    std::size_t written = 2; // the zlib header
    // RFC 1950: deflate with a 32 KB window (0x78); "fastest" (FLEVEL 0), FCHECK making the pair a
    // multiple of 31.
    out.push_back(0x78);
    out.push_back(0x01);
    std::size_t bitOffset = 0; // bits of the last byte written already used (blocks are not byte-aligned)
    std::uint64_t carry = 0; // those bits
    std::size_t i = 0;
    bool last = false;
    while (!last) {
        std::size_t count = 0;
        while (count < kBlockTokens && i < size) {
            std::size_t distance = 0;
            std::size_t length = search.at(i, distance, true);
            // One step lazy: a literal here when the match one byte on is longer by two or more.
            if (length >= kMinMatch && length < kGoodMatch && i + 1 < size) {
                std::size_t ignored = 0;
                if (search.at(i + 1, ignored, false) > length + 1)
                    length = 0;
            }
            if (length >= kMinMatch) {
                tokens[count++] = (Token(length) << 16) | Token(distance - 1);
                i += length;
            } else {
                tokens[count++] = data[i];
                ++i;
            }
        }
        last = i >= size;
        BlockCodes& block = scratch.block;
        block.make(tokens, count);
        // The block's bytes, the carried bits of the last byte before it included.
        const std::size_t blockBytes = std::size_t((bitOffset + block.bits + 7) / 8);
        if (written - (bitOffset > 0 ? 1 : 0) + blockBytes + 4 > limit) {
            out.resize(start);
            return false;
        }
        if (bitOffset > 0)
            out.pop_back(); // its bits are carried into the block's first byte
        const std::size_t at = out.size();
        out.resize(at + blockBytes + 8); // BitWriter stores whole 32-bit words
        BitWriter w(out.data() + at);
        if (bitOffset > 0)
            w.put(std::uint32_t(carry), int(bitOffset));
        block.write(w, tokens, count, last);
        unsigned char* end = w.finish();
        out.resize(std::size_t(end - out.data()));
        bitOffset = std::size_t((bitOffset + block.bits) % 8);
        carry = bitOffset > 0 ? out.back() : 0;
        written = out.size() - start;
    }
    const std::uint32_t adler = libdeflate_adler32(1, data, size);
    for (int k = 3; k >= 0; --k)
        out.push_back(static_cast<unsigned char>(adler >> (8 * k)));
    return true;
}

} // namespace celform::model
