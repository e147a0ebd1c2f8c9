// Render output through OpenImageIO (the module of raster_codec.h).
#include "celform/model/render/render_output.h"

#include "celform/model/analysis/depth_analysis_output.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/exr_encoder.h"
#include "celform/model/io/image_io.h"
#include "celform/model/io/output_file.h"
#include "celform/model/io/png_encoder.h"
#include "celform/model/io/raster_codec.h"
#include "celform/model/render/ridge_depth_prepass.h"

#include "celform/algorithms/srgb_encode.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace celform::model {
namespace {

struct RenderOutput {
    Q_DECLARE_TR_FUNCTIONS(celform::model::RenderOutput)
};

} // namespace

namespace {

/// The channel list of an EXR being written, per thread (its names' storage kept between frames).
std::vector<ExrChannelSource>& exrSources()
{
    thread_local std::vector<ExrChannelSource> sources;
    return sources;
}

/// The thread's encoded file, reused frame after frame (issue 29).
std::vector<unsigned char>& encodedFile()
{
    thread_local std::vector<unsigned char> encoded;
    return encoded;
}

/// path's suffix in lower case when it is an image type Celform writes; else IoError naming it.
QString imageSuffix(const QString& path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    const QStringList known = {QStringLiteral("png"), QStringLiteral("tif"), QStringLiteral("tiff"),
        QStringLiteral("jpg"), QStringLiteral("jpeg"), QStringLiteral("exr")};
    if (!known.contains(suffix))
        throw IoError(path, RenderOutput::tr("has an unknown image type; use .png, .tif, .jpg or .exr"));
    return suffix;
}

/// An EXR of sources encoded in memory by exr_encoder.h (OpenEXRCore and libdeflate, without the
/// OpenImageIO module), then written whole or not at all.
void writeExr(const QString& path, int width, int height, const std::vector<ExrChannelSource>& sources)
{
    std::vector<unsigned char>& encoded = encodedFile();
    const QString error = encodeExr(width, height, sources, encoded);
    if (!error.isEmpty())
        throw IoError(path, RenderOutput::tr("could not be written: %1").arg(error));
    writeWholeFile(path, encoded.data(), qint64(encoded.size()), Durability::Renamed);
}

/// How many channels the PNG encoder takes for these names (R G B A, R G B or one channel), 0 when
/// the PNG goes through OpenImageIO instead.
int pngChannelsOf(const std::vector<std::string>& names)
{
    if (names == std::vector<std::string>{"R", "G", "B", "A"})
        return 4;
    if (names == std::vector<std::string>{"R", "G", "B"})
        return 3;
    return names.size() == 1 ? 1 : 0;
}

} // namespace

void encodeChannels(const QString& path, int width, int height, const std::vector<std::string>& names,
    const float* data, std::size_t count, bool encodeSrgb, EncodedFrame& out)
{
    if (imageSuffix(path) == QLatin1String("exr"))
        throw IoError(path, RenderOutput::tr("is an EXR, whose floats are not quantised"));
    out.width = width;
    out.height = height;
    out.names = names;
    const int channels = int(names.size());
    out.bytes.resize(count);
    // The colour channels come first (at most three), alpha or data after them.
    int colour = std::min(channels, 3);
    for (int c = 0; c < colour; ++c)
        if (names[std::size_t(c)] == "A")
            colour = c;
    algo::quantise8(data, out.bytes.data(), count, channels, colour, encodeSrgb);
}

void writeEncoded(const EncodedFrame& image, const QString& path)
{
    // Encoded in memory, then written whole or not at all: a full disk is an IoError naming the
    // file and the reason, and leaves neither a short file nor a temporary one (issue 27). Kept
    // per thread: a sequence's writer reuses them frame after frame (issue 29). Frames are not
    // synced to the disk one by one (docs/farm.md).
    std::vector<unsigned char>& encoded = encodedFile();
    const QString suffix = QFileInfo(path).suffix().toLower();
    // 8-bit PNGs by Celform's writer over libdeflate (png_encoder.h): faster than Qt's writer, and
    // without loading the OpenImageIO module and its library graph (about 275 libraries), which
    // issue 29 measured as the larger part of a one-frame render's start.
    const int pngChannels = pngChannelsOf(image.names);
    const QString error = suffix == QLatin1String("png") && pngChannels > 0
        ? encodePng(image.bytes.data(), image.width, image.height, pngChannels, encoded)
        : rasterCodec(path).encode(suffix, image.width, image.height, image.names, image.bytes.data(), &encoded);
    if (!error.isEmpty())
        throw IoError(path, RenderOutput::tr("could not be written: %1").arg(error));
    writeWholeFile(path, encoded.data(), qint64(encoded.size()), Durability::Renamed);
}

void writeChannelsFile(const QString& path, int width, int height, const std::vector<std::string>& names,
    const float* data, std::size_t count, bool encodeSrgb, EncodedFrame* scratch)
{
    if (imageSuffix(path) != QLatin1String("exr")) {
        EncodedFrame local;
        EncodedFrame& encoded = scratch ? *scratch : local;
        encodeChannels(path, width, height, names, data, count, encodeSrgb, encoded);
        writeEncoded(encoded, path);
        return;
    }
    // The floats as they are, read where they lie (no copy of the image is made).
    std::vector<ExrChannelSource>& sources = exrSources();
    sources.resize(names.size());
    for (std::size_t c = 0; c < sources.size(); ++c)
        sources[c] = {names[c], data + c, names.size(), ExrChannelSource::Kind::Float};
    writeExr(path, width, height, sources);
}

algo::RenderLook renderLookFor(
    const ProjectData& data, const Look& look, const std::vector<float>* shadingOffsets, int frame)
{
    algo::RenderLook r;
    auto toAlgo = [](ShadingStyle s) {
        switch (s) {
        case ShadingStyle::Lambert:
            return algo::Style::Lambert;
        case ShadingStyle::Gooch:
            return algo::Style::Gooch;
        case ShadingStyle::Comic:
            return algo::Style::Comic;
        case ShadingStyle::Toon:
            break;
        }
        return algo::Style::Toon;
    };
    r.style = toAlgo(look.style);
    const std::size_t materials = data.baseMesh ? data.baseMesh->materials.size() : 0;
    for (std::size_t m = 0; m < std::max<std::size_t>(materials, 1); ++m) {
        r.materialStyles.push_back(toAlgo(look.styleOf(int(m))));
        r.materialColors.push_back(m < materials ? data.baseMesh->materials[m].baseColor : r.defaultColor);
    }
    r.background = look.backgroundColor;
    const Light light = look.lightAt(double(frame));
    r.pointLight = light.type == LightType::Point;
    r.light = light.vector.cast<float>();
    r.toon = look.toon;
    r.toonEvaluation = look.toonEvaluation;
    r.gooch = look.gooch;
    if (look.gooch.preset == "auto") {
        // Paper 1, section 3.2.4: the coefficients follow each material's hue; the artist's
        // warm and cool colours stay.
        for (const algo::Color& base : r.materialColors) {
            algo::GoochParams p = algo::goochPresetForColor(base);
            p.warm = look.gooch.warm;
            p.cool = look.gooch.cool;
            r.materialGooch.push_back(p);
        }
        r.gooch = r.materialGooch.front();
    }
    r.hatch = look.hatch;
    r.lines = look.showLines;
    r.lineSettings = look.lines;
    r.lineStyle = look.lineStyle;
    const std::vector<float>& offsets = shadingOffsets ? *shadingOffsets : data.shadingOffsets;
    r.shadingOffsets = offsets.empty() ? nullptr : &offsets;
    return r;
}

/// Rounds of neighbour averaging of a guide's projections: enough to fill the spots where the guide
/// is nearly normal to the surface without washing out the artist's direction.
constexpr int kGuideSmoothingRounds = 4;

namespace {

/// 64-bit FNV-1a over raw bytes, chained through seed.
std::uint64_t hashBytes(const void* bytes, std::size_t size, std::uint64_t seed = 14695981039346656037ull)
{
    const auto* p = static_cast<const unsigned char*>(bytes);
    std::uint64_t h = seed;
    for (std::size_t i = 0; i < size; ++i)
        h = (h ^ p[i]) * 1099511628211ull;
    return h;
}

constexpr std::size_t kHighlightGeometryEntries = 8;

} // namespace

std::vector<algo::RenderHighlight> renderHighlightsFor(const ProjectData& data, const Look& look,
    const algo::Positions& shape, int frame, algo::RenderCache* cache, std::uint64_t shapeGeneration)
{
    if (shapeGeneration == 0)
        cache = nullptr; // positions of unknown origin: nothing to recognise them by
    std::vector<algo::RenderHighlight> out;
    if (look.highlights.empty() || !data.baseMesh)
        return out;
    const algo::TriMesh& mesh = *data.baseMesh;
    // The normals and UV frames are shared by every track, and by every frame while the shape
    // keeps its generation (issue 29: a sequence of a still shape derived them frame after frame).
    algo::HighlightShapeFrames once;
    algo::HighlightShapeFrames& frames = cache ? cache->highlightFrames : once;
    if (!cache || frames.generation != shapeGeneration) {
        algo::vertexNormals(shape, mesh.faces, frames.normals);
        frames.haveUvFrames = false;
        if (mesh.hasUvs()) {
            // A copy of the mesh carries the deformed positions.
            algo::TriMesh deformed = mesh;
            deformed.vertices = shape;
            frames.haveUvFrames = algo::vertexTangentFramesFromUvs(deformed, frames.normals, frames.du, frames.dv);
        }
        frames.generation = cache ? shapeGeneration : 0;
    }
    const algo::Positions& normals = frames.normals;
    const algo::Positions& uvDu = frames.du;
    const algo::Positions& uvDv = frames.dv;
    const bool haveUvFrames = frames.haveUvFrames;
    // The shape is known by its generation (never reused in a process): no pass over its positions.
    const std::uint64_t shapeKey = hashBytes(&shapeGeneration, sizeof(shapeGeneration));
    auto shapeOf = [&](const QString& name) -> std::optional<algo::HighlightShape> {
        for (const HighlightTrack& t : look.highlights)
            if (t.name == name)
                return t.layerAt(frame).shape;
        return std::nullopt;
    };
    for (const HighlightTrack& track : look.highlights) {
        if (!track.visible || track.keys.empty())
            continue;
        algo::RenderHighlight h;
        h.layer = track.layerAt(frame);
        h.layer.name = track.name.toStdString();
        h.layer.combinations.clear();
        for (const auto& [mode, other] : track.combineWith)
            if (const auto otherShape = shapeOf(other))
                h.layer.combinations.push_back({mode, *otherShape});
        std::vector<std::int32_t> patchFaces;
        if (!track.patch.isEmpty() && track.patch != QLatin1String("all")) {
            const algo::FaceSet* set = data.faceSet(track.patch);
            if (!set)
                continue; // validated on load and edit; a stale name draws nothing
            patchFaces.assign(set->faces.begin(), set->faces.end());
            h.faceMask.assign(std::size_t(mesh.faces.rows()), 0);
            for (const auto f : patchFaces)
                h.faceMask[std::size_t(f)] = 1;
        }
        // The geometry depends on the shape, the faces, the patch, the guide and the smoothing.
        std::uint64_t key = 0;
        if (cache) {
            key = hashBytes(patchFaces.data(), sizeof(std::int32_t) * patchFaces.size(), shapeKey);
            key = hashBytes(track.guide.data(), sizeof(float) * 3, key);
            key = hashBytes(&track.smoothing, sizeof(track.smoothing), key);
            key = hashBytes(&haveUvFrames, sizeof(haveUvFrames), key);
            auto& entries = cache->highlights;
            const auto hit = std::find_if(
                entries.begin(), entries.end(), [key](const algo::HighlightGeometry& g) { return g.key == key; });
            if (hit != entries.end()) {
                h.normals = hit->normals;
                h.du = hit->du;
                h.dv = hit->dv;
                std::rotate(hit, hit + 1, entries.end()); // most recently used last
                out.push_back(std::move(h));
                continue;
            }
        }
        // Smoothed normals stand in for the paper's smooth patch; the guide's frames follow them
        // (UV frames stay: every pixel orthonormalises its frame against its normal anyway).
        if (track.smoothing > 0
            && !algo::smoothPatchNormals(shape, mesh.faces, normals, patchFaces, track.smoothing, h.normals))
            continue;
        const algo::Positions& layerNormals = h.normals.rows() > 0 ? h.normals : normals;
        if (haveUvFrames) {
            h.du = uvDu;
            h.dv = uvDv;
        } else if (!algo::guideVertexFrames(
                       shape, mesh.faces, layerNormals, patchFaces, track.guide, kGuideSmoothingRounds, h.du, h.dv)) {
            continue;
        }
        if (cache) {
            auto& entries = cache->highlights;
            if (entries.size() >= kHighlightGeometryEntries)
                entries.erase(entries.begin());
            entries.push_back({key, h.normals, h.du, h.dv});
        }
        out.push_back(std::move(h));
    }
    return out;
}

algo::RasterCamera rasterCamera(const Camera& camera, int width, int height)
{
    algo::RasterCamera r;
    r.eye = camera.eye;
    r.target = camera.target;
    r.up = camera.up;
    r.orthographic = camera.projection == Projection::Orthographic;
    r.fovYDegrees = camera.fovYDegrees;
    r.orthoHeight = camera.orthoHeight;
    r.width = width;
    r.height = height;
    return r;
}

algo::StereoSettings resolvedStereo(const StereoLook& stereo, const Camera& camera, const Eigen::Vector3d& centroid)
{
    algo::StereoSettings s;
    const double depth = std::max((centroid - camera.eye).dot(camera.forward()), 1e-6);
    s.convergence = stereo.convergence > 0 ? stereo.convergence : depth;
    s.interocular = stereo.interocular > 0 ? stereo.interocular : s.convergence / 30.0;
    s.toeIn = stereo.toeIn;
    s.swapEyes = stereo.swapEyes;
    return s;
}

std::vector<algo::RenderPasses> renderEyes(const ProjectData& data, const Look& look, const algo::Positions& shape,
    int frame, const Camera& camera, int width, int height, algo::StereoOutput stereo, algo::RenderCache& cache,
    std::uint64_t shapeGeneration, const std::vector<float>* shadingOffsets, bool withCentre,
    const algo::Positions* vertexNormals)
{
    algo::RenderLook renderLook = renderLookFor(data, look, shadingOffsets, frame);
    renderLook.vertexNormals = vertexNormals;
    renderLook.highlights = renderHighlightsFor(data, look, shape, frame, &cache, shapeGeneration);
    const algo::RasterCamera centre = rasterCamera(camera, width, height);
    // The ridges' depth-driven threshold from the centre eye's picture (paper 3, 4.4), both eyes alike.
    prepareDepthAdaptedRidges(*data.baseMesh, shape, centre, renderLook, cache, threadRidgeDepthPrepass());
    const bool mono = stereo == algo::StereoOutput::Off;
    std::vector<algo::RenderPasses> eyes((mono || withCentre ? 1 : 0) + (mono ? 0 : 2));
    if (mono || withCentre)
        algo::renderFrame(shape, *data.baseMesh, centre, renderLook, cache, eyes.front());
    if (mono)
        return eyes;
    const auto [left, right] = algo::stereoPair(centre, resolvedStereo(look.stereo, camera, data.baseMesh->centre()));
    // Both eyes take their lines from the centre eye (paper 3, section 4.2.2).
    algo::renderFrame(shape, *data.baseMesh, left, renderLook, cache, eyes[eyes.size() - 2], &centre);
    algo::renderFrame(shape, *data.baseMesh, right, renderLook, cache, eyes.back(), &centre);
    return eyes;
}

algo::RenderPasses renderShape(const ProjectData& data, const Look& look, const algo::Positions& shape, int frame,
    const Camera& camera, int width, int height, algo::StereoOutput stereo, algo::RenderCache& cache,
    std::uint64_t shapeGeneration, const std::vector<float>* shadingOffsets, const algo::Positions* vertexNormals)
{
    algo::RenderPasses passes;
    renderShape(data, look, shape, frame, camera, width, height, stereo, cache, passes, shapeGeneration, shadingOffsets,
        vertexNormals);
    return passes;
}

void renderShape(const ProjectData& data, const Look& look, const algo::Positions& shape, int frame,
    const Camera& camera, int width, int height, algo::StereoOutput stereo, algo::RenderCache& cache,
    algo::RenderPasses& passes, std::uint64_t shapeGeneration, const std::vector<float>* shadingOffsets,
    const algo::Positions* vertexNormals, bool dataPasses)
{
    if (stereo == algo::StereoOutput::Off) {
        // Mono: straight into passes, whose buffers a sequence keeps (issue 29).
        algo::RenderLook renderLook = renderLookFor(data, look, shadingOffsets, frame);
        renderLook.vertexNormals = vertexNormals;
        renderLook.dataPasses = dataPasses;
        renderLook.highlights = renderHighlightsFor(data, look, shape, frame, &cache, shapeGeneration);
        const algo::RasterCamera raster = rasterCamera(camera, width, height);
        prepareDepthAdaptedRidges(*data.baseMesh, shape, raster, renderLook, cache, threadRidgeDepthPrepass());
        algo::renderFrame(shape, *data.baseMesh, raster, renderLook, cache, passes);
        return;
    }
    std::vector<algo::RenderPasses> eyes = renderEyes(data, look, shape, frame, camera, width, height, stereo, cache,
        shapeGeneration, shadingOffsets, true, vertexNormals);
    passes = std::move(eyes[0]);
    const algo::RenderPasses& l = eyes[1];
    const algo::RenderPasses& r = eyes[2];
    switch (stereo) {
    case algo::StereoOutput::Anaglyph:
        passes.beauty = algo::composeAnaglyph(l.beauty, r.beauty);
        break;
    case algo::StereoOutput::Dubois:
        passes.beauty = algo::composeDubois(l.beauty, r.beauty, look.stereo.dubois);
        break;
    case algo::StereoOutput::HalfColor:
        passes.beauty = algo::composeHalfColor(l.beauty, r.beauty);
        break;
    case algo::StereoOutput::SideBySide:
        passes.beauty = algo::composeSideBySide(l.beauty, r.beauty);
        break;
    case algo::StereoOutput::TopBottom:
        passes.beauty = algo::composeTopBottom(l.beauty, r.beauty);
        break;
    case algo::StereoOutput::Off:
        break;
    }
}

QStringList renderPassNames()
{
    return QStringList{QStringLiteral("beauty"), QStringLiteral("lines"), QStringLiteral("tone"),
               QStringLiteral("highlights"), QStringLiteral("depth"), QStringLiteral("normal"), QStringLiteral("id")}
    + analysisPassNames();
}

algo::ImageRGBA passImage(const algo::RenderPasses& passes, const QString& pass, bool forFloatFile)
{
    if (pass == QLatin1String("beauty"))
        return passes.beauty;
    algo::ImageRGBA image;
    passImage(passes, pass, forFloatFile, image);
    return image;
}

void passImage(const algo::RenderPasses& passes, const QString& pass, bool forFloatFile, algo::ImageRGBA& image)
{
    const int w = passes.beauty.width, h = passes.beauty.height;
    if (pass == QLatin1String("beauty")) {
        image = passes.beauty; // copy-assigned into the storage image has
        return;
    }
    image.width = w;
    image.height = h;
    image.pixels.resize(std::size_t(w) * std::size_t(h) * 4);
    for (std::size_t i = 0; i < image.pixels.size(); i += 4) {
        image.pixels[i] = image.pixels[i + 1] = image.pixels[i + 2] = 0.f;
        image.pixels[i + 3] = 1.f;
    }
    auto grey = [&](const std::vector<float>& values) {
        for (int i = 0; i < w * h; ++i)
            for (int c = 0; c < 3; ++c)
                image.pixels[std::size_t(i) * 4 + std::size_t(c)] = values[std::size_t(i)];
    };
    if (pass == QLatin1String("lines")) {
        grey(passes.lines);
    } else if (pass == QLatin1String("tone")) {
        grey(passes.tone);
    } else if (pass == QLatin1String("highlights")) {
        grey(passes.highlights);
    } else if (pass == QLatin1String("depth")) {
        std::vector<float> d(passes.depth.size(), 0.f);
        float lo = std::numeric_limits<float>::max(), hi = 0.f;
        for (float v : passes.depth)
            if (std::isfinite(v)) {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
        for (std::size_t i = 0; i < d.size(); ++i) {
            const float v = passes.depth[i];
            if (!std::isfinite(v))
                d[i] = forFloatFile ? 0.f : 1.f;
            else
                d[i] = forFloatFile ? v : (hi > lo ? (v - lo) / (hi - lo) : 0.f);
        }
        grey(d);
    } else if (pass == QLatin1String("normal")) {
        for (int i = 0; i < w * h; ++i) {
            const Eigen::Vector3f n = passes.normal[std::size_t(i)];
            for (int c = 0; c < 3; ++c)
                image.pixels[std::size_t(i) * 4 + std::size_t(c)]
                    = forFloatFile ? n[c] : (n == Eigen::Vector3f::Zero() ? 0.f : 0.5f * n[c] + 0.5f);
        }
    } else if (pass == QLatin1String("id")) {
        for (int i = 0; i < w * h; ++i) {
            const std::int32_t id = passes.id[std::size_t(i)];
            if (forFloatFile) {
                for (int c = 0; c < 3; ++c)
                    image.pixels[std::size_t(i) * 4 + std::size_t(c)] = float(id);
                continue;
            }
            if (id < 0)
                continue;
            // A hash spreads neighbouring ids over distinct colours.
            std::uint32_t hsh = std::uint32_t(id) * 2654435761u;
            hsh ^= hsh >> 15;
            for (int c = 0; c < 3; ++c)
                image.pixels[std::size_t(i) * 4 + std::size_t(c)]
                    = algo::srgbToLinear(float((hsh >> (8 * c)) & 0xffu) / 255.f);
        }
    } else {
        throw IoError(pass,
            RenderOutput::tr("is not a render pass; use one of %1").arg(renderPassNames().join(QStringLiteral(", "))));
    }
}

void writeImage(const algo::ImageRGBA& image, const QString& path)
{
    writeChannelsFile(
        path, image.width, image.height, {"R", "G", "B", "A"}, image.pixels.data(), image.pixels.size(), true);
}

void writeImageChannels(const QString& path, int width, int height, const std::vector<std::string>& names,
    const std::vector<float>& data, bool encodeSrgb)
{
    writeChannelsFile(path, width, height, names, data.data(), data.size(), encodeSrgb);
}

QString incompleteImageProblem(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return file.errorString();
    const QByteArray bytes = file.readAll();
    try {
        // The frames are this program's own files: decoded here, not in an import child.
        decodeImage(bytes, QFileInfo(path).suffix(), path, ImportIsolation::ThisProcess);
    } catch (const IoError& e) {
        return e.problem();
    }
    return {};
}

void writePassesExr(const algo::RenderPasses& passes, const QString& path)
{
    if (QFileInfo(path).suffix().toLower() != QLatin1String("exr"))
        throw IoError(path, RenderOutput::tr("all passes together need an .exr file"));
    const int w = passes.beauty.width, h = passes.beauty.height;
    const std::size_t pixels = std::size_t(w) * std::size_t(h);
    if (passes.beauty.pixels.size() != pixels * 4 || passes.lines.size() != pixels || passes.tone.size() != pixels
        || passes.highlights.size() != pixels || passes.depth.size() != pixels || passes.normal.size() != pixels
        || passes.id.size() != pixels)
        throw IoError(path, RenderOutput::tr("could not be written: the render has no data passes"));
    // The channels are read where the render left them, scanline by scanline (exr_encoder.h).
    static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "normals are packed");
    using Kind = ExrChannelSource::Kind;
    const float* beauty = passes.beauty.pixels.data();
    const float* normal = passes.normal.data()->data();
    std::vector<ExrChannelSource>& sources = exrSources();
    sources = {{"R", beauty, 4, Kind::Float}, {"G", beauty + 1, 4, Kind::Float}, {"B", beauty + 2, 4, Kind::Float},
        {"A", beauty + 3, 4, Kind::Float}, {"lines.Y", passes.lines.data(), 1, Kind::Float},
        {"tone.Y", passes.tone.data(), 1, Kind::Float}, {"highlights.Y", passes.highlights.data(), 1, Kind::Float},
        {"depth.Z", passes.depth.data(), 1, Kind::FiniteFloat}, {"normal.X", normal, 3, Kind::Float},
        {"normal.Y", normal + 1, 3, Kind::Float}, {"normal.Z", normal + 2, 3, Kind::Float},
        {"id.ID", passes.id.data(), 1, Kind::Int32}};
    writeExr(path, w, h, sources);
}

} // namespace celform::model
