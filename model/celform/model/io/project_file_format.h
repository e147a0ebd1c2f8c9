// What the .celform reader and writer share (layout in docs/file-format.md): the magic numbers,
// the CRC-32 of the chunks and the stable names of the enums. Internal to project_file*.cpp.
#pragma once

#include "celform/algorithms/highlights.h"
#include "celform/algorithms/stereo.h"
#include "celform/algorithms/shading.h"
#include "celform/model/data/project_data.h"

#include <QCoreApplication>
#include <QString>
#include <QtEndian>

#include <libdeflate.h>

#include <algorithm>
#include <utility>

namespace celform::model::project_format {

static_assert(Q_BYTE_ORDER == Q_LITTLE_ENDIAN, "the chunk layout is little-endian; add byte swapping first");

// Gives lupdate the context "celform::model::ProjectFile" for every ProjectFile::tr() below.
struct ProjectFile {
    Q_DECLARE_TR_FUNCTIONS(celform::model::ProjectFile)
};

using Vec3 = Eigen::Vector3d; // an alias: lupdate misreads a qualified return type as a context

constexpr char kMagic[8] = {'\x89', 'C', 'E', 'L', 'F', '\r', '\n', '\x1a'};
constexpr char kEndMagic[8] = {'C', 'E', 'L', 'F', 'E', 'N', 'D', '\n'};
constexpr qint64 kHeaderSize = 16;
constexpr qint64 kTrailerSize = 32;

/// CRC-32 (ISO 3309, as zlib's crc32) of the chunks and the manifest, by libdeflate: several times
/// as fast as zlib's on this machine's processors (carry-less multiplication), 5 ms of the dragon's
/// 16 MB project at every load before (issue 29: a render's start).
inline quint32 crc32Of(const char* data, qint64 size)
{
    return quint32(libdeflate_crc32(0, data, size > 0 ? std::size_t(size) : 0));
}

// --- enums as stable strings ------------------------------------------------------------------

template <typename E> struct EnumNames;
template <> struct EnumNames<UnspecifiedMode> {
    static constexpr std::pair<UnspecifiedMode, const char*> list[] = {
        {UnspecifiedMode::Dummy, "dummy"}, {UnspecifiedMode::Cosine, "cosine"}, {UnspecifiedMode::Cosine2, "cosine2"}};
};
template <> struct EnumNames<TimeInterpolation> {
    static constexpr std::pair<TimeInterpolation, const char*> list[]
        = {{TimeInterpolation::NaturalSpline, "natural"}, {TimeInterpolation::PeriodicSpline, "periodic"}};
};
template <> struct EnumNames<ShadingStyle> {
    static constexpr std::pair<ShadingStyle, const char*> list[] = {{ShadingStyle::Lambert, "lambert"},
        {ShadingStyle::Toon, "toon"}, {ShadingStyle::Gooch, "gooch"}, {ShadingStyle::Comic, "comic"}};
};
template <> struct EnumNames<LightType> {
    static constexpr std::pair<LightType, const char*> list[]
        = {{LightType::Directional, "directional"}, {LightType::Point, "point"}};
};
template <> struct EnumNames<Projection> {
    static constexpr std::pair<Projection, const char*> list[]
        = {{Projection::Perspective, "perspective"}, {Projection::Orthographic, "orthographic"}};
};

template <> struct EnumNames<algo::ToonEvaluation> {
    static constexpr std::pair<algo::ToonEvaluation, const char*> list[] = {{algo::ToonEvaluation::PerPixel, "pixel"},
        {algo::ToonEvaluation::PerVertexLut, "vertex_lut"}, {algo::ToonEvaluation::PerFace, "face"}};
};
template <> struct EnumNames<algo::StereoOutput> {
    static constexpr std::pair<algo::StereoOutput, const char*> list[]
        = {{algo::StereoOutput::Off, "off"}, {algo::StereoOutput::Anaglyph, "anaglyph"},
            {algo::StereoOutput::Dubois, "dubois"}, {algo::StereoOutput::HalfColor, "halfcolor"},
            {algo::StereoOutput::SideBySide, "sbs"}, {algo::StereoOutput::TopBottom, "tb"}};
};

template <typename E> QString enumName(E value)
{
    for (const auto& [v, name] : EnumNames<E>::list)
        if (v == value)
            return QString::fromLatin1(name);
    return {};
}

} // namespace celform::model::project_format
