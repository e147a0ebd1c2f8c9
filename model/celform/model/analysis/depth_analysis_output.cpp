// Pictures and files of the depth analysis (depth_analysis_output.h).
#include "celform/model/analysis/depth_analysis_output.h"

#include "celform/model/analysis/depth_analysis.h"
#include "celform/model/data/io_error.h"
#include "celform/model/io/output_file.h"
#include "celform/model/render/render_output.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QtEndian>

#include <algorithm>
#include <cmath>
#include <string>

namespace celform::model {
namespace {

/// The 98th percentile of |values| over the model's pixels (depth finite): the saturation point
/// of a diverging picture, so that a few extreme pixels at creases do not wash the rest out.
float robustScale(const std::vector<float>& values, const std::vector<float>& depth)
{
    std::vector<float> magnitudes;
    magnitudes.reserve(values.size());
    for (std::size_t i = 0; i < values.size() && i < depth.size(); ++i)
        if (std::isfinite(depth[i]) && std::isfinite(values[i]))
            magnitudes.push_back(std::abs(values[i]));
    if (magnitudes.empty())
        return 0.f;
    const auto at = magnitudes.begin() + std::ptrdiff_t(double(magnitudes.size() - 1) * 0.98);
    std::nth_element(magnitudes.begin(), at, magnitudes.end());
    return *at;
}

/// Light grey at zero (sRGB 0.86, so the model stays apart from a white page), towards positive at
/// +1 and negative at -1 (linear RGB).
Eigen::Vector3f diverging(float t, const Eigen::Vector3f& positive, const Eigen::Vector3f& negative)
{
    const float a = std::clamp(std::abs(t), 0.f, 1.f);
    const Eigen::Vector3f& end = t >= 0.f ? positive : negative;
    const float neutral = 0.7157f; // srgbToLinear(0.86)
    return Eigen::Vector3f::Constant(neutral) * (1.f - a) + end * a;
}

} // namespace

QStringList analysisPassNames()
{
    return {QStringLiteral("segments"), QStringLiteral("curvature"), QStringLiteral("depth-error")};
}

std::optional<AnalysisPicture> analysisPictureFromName(const QString& name)
{
    if (name == QLatin1String("segments"))
        return AnalysisPicture::Segments;
    if (name == QLatin1String("curvature"))
        return AnalysisPicture::Curvature;
    if (name == QLatin1String("depth-error"))
        return AnalysisPicture::DepthError;
    return std::nullopt;
}

Eigen::Vector3f segmentColor(int id)
{
    // Hue by the golden angle, full saturation, two alternating values: fifty segments stay apart.
    const float hue = std::fmod(float(id) * 0.381966f + 0.08f, 1.f) * 6.f;
    const float value = id % 2 == 0 ? 0.9f : 0.62f;
    const float saturation = 0.75f;
    const int sector = int(hue) % 6;
    const float f = hue - std::floor(hue);
    const float p = value * (1.f - saturation), q = value * (1.f - saturation * f),
                t = value * (1.f - saturation * (1.f - f));
    Eigen::Vector3f srgb;
    switch (sector) {
    case 0:
        srgb = {value, t, p};
        break;
    case 1:
        srgb = {q, value, p};
        break;
    case 2:
        srgb = {p, value, t};
        break;
    case 3:
        srgb = {p, q, value};
        break;
    case 4:
        srgb = {t, p, value};
        break;
    default:
        srgb = {value, p, q};
        break;
    }
    return {algo::srgbToLinear(srgb.x()), algo::srgbToLinear(srgb.y()), algo::srgbToLinear(srgb.z())};
}

algo::ImageRGBA analysisImage(const algo::DepthAnalysis& a, AnalysisPicture picture, bool forFloatFile, float* scaleOut)
{
    const int w = a.width, h = a.height;
    const std::size_t count = std::size_t(w) * std::size_t(h);
    algo::ImageRGBA image(w, h, Eigen::Vector4f(0, 0, 0, 0));
    if (a.depth.size() != count)
        return image;
    // Orange and blue of the thesis's figures 4.5 and 4.17, in linear light.
    const Eigen::Vector3f orange(algo::srgbToLinear(0.96f), algo::srgbToLinear(0.50f), algo::srgbToLinear(0.05f));
    const Eigen::Vector3f blue(algo::srgbToLinear(0.10f), algo::srgbToLinear(0.35f), algo::srgbToLinear(0.95f));
    float scale = 0.f;
    if (picture == AnalysisPicture::Curvature)
        scale = a.curvatureScale > 0.f ? a.curvatureScale : robustScale(a.curvature, a.depth);
    else if (picture == AnalysisPicture::DepthError)
        scale = robustScale(a.depthError, a.depth);
    if (scaleOut)
        *scaleOut = scale;
    const float inverse = scale > 0.f ? 1.f / scale : 0.f;
    for (std::size_t i = 0; i < count; ++i) {
        float* px = image.pixels.data() + i * 4;
        const bool onModel = std::isfinite(a.depth[i]);
        float raw = 0.f;
        Eigen::Vector3f colour = Eigen::Vector3f::Zero();
        bool visible = onModel;
        switch (picture) {
        case AnalysisPicture::Segments: {
            const std::int32_t id = i < a.segments.labels.size() ? a.segments.labels[i] : -1;
            raw = float(id);
            visible = onModel && id >= 0;
            if (visible)
                colour = segmentColor(id);
            break;
        }
        case AnalysisPicture::Curvature:
            raw = a.curvature[i];
            colour = diverging(raw * inverse, orange, blue);
            break;
        case AnalysisPicture::DepthError:
            // Positive error: the nearest feature is farther than the pixel, so it is perceived
            // farther than it is (blue, figure 4.17's caption).
            raw = i < a.depthError.size() ? a.depthError[i] : 0.f;
            colour = diverging(raw * inverse, blue, orange);
            break;
        }
        if (forFloatFile) {
            px[0] = px[1] = px[2] = onModel ? raw : (picture == AnalysisPicture::Segments ? -1.f : 0.f);
            px[3] = onModel ? 1.f : 0.f;
        } else if (visible) {
            px[0] = colour.x();
            px[1] = colour.y();
            px[2] = colour.z();
            px[3] = 1.f;
        }
    }
    return image;
}

void writeAnalysisExr(const FrameAnalysis& frame, const QString& path)
{
    const algo::DepthAnalysis& a = frame.analysis;
    const algo::ImageRGBA& beauty = frame.passes.beauty;
    if (QFileInfo(path).suffix().toLower() != QLatin1String("exr"))
        throw IoError(
            path, QCoreApplication::translate("celform::model::RenderOutput", "the analysis needs an .exr file"));
    const int w = a.width, h = a.height;
    const std::vector<std::string> names
        = {"R", "G", "B", "A", "curvature.K", "segment.ID", "depth.Z", "depth_error.Z", "feature.Y",
            // Figure 4.3: the shading N.L (plus the shading offset, the value the toon threshold
            // cuts) and its derivative with respect to the light position (eq. 4.2).
            "shading.NdotL", "light_gradient.X", "light_gradient.Y", "light_gradient.Z"};
    const std::size_t channels = names.size();
    const std::size_t count = std::size_t(w) * std::size_t(h);
    std::vector<float> data(count * channels);
    for (std::size_t i = 0; i < count; ++i) {
        float* p = data.data() + i * channels;
        for (std::size_t c = 0; c < 4; ++c)
            p[c] = beauty.pixels.size() == count * 4 ? beauty.pixels[i * 4 + c] : 0.f;
        p[4] = a.curvature[i];
        p[5] = float(a.segments.labels[i]);
        p[6] = std::isfinite(a.depth[i]) ? a.depth[i] : 0.f;
        p[7] = a.depthError[i];
        p[8] = float(a.feature[i]);
        p[9] = a.lambert.size() == count ? a.lambert[i] : 0.f;
        const Eigen::Vector3f g = a.lightGradient.size() == count ? a.lightGradient[i] : Eigen::Vector3f::Zero();
        p[10] = g.x();
        p[11] = g.y();
        p[12] = g.z();
    }
    writeImageChannels(path, w, h, names, data, false);
}

void writeCurvaturePly(
    const algo::Positions& shape, const algo::Faces& faces, const algo::Curvatures& curvature, const QString& path)
{
    const std::size_t vertices = std::size_t(shape.rows());
    if (curvature.k1.size() != vertices || curvature.k2.size() != vertices || curvature.gaussian.size() != vertices)
        throw IoError(path,
            QCoreApplication::translate("celform::model::RenderOutput", "the curvature does not match the shape"));
    const std::string header = "ply\nformat binary_little_endian 1.0\ncomment Written by Celform: principal curvatures "
                               "(Rusinkiewicz 2004)\nelement vertex "
        + std::to_string(vertices)
        + "\nproperty float x\nproperty float y\nproperty float z\nproperty float k1\nproperty float k2\n"
          "property float K\nproperty float K_smooth\nelement face "
        + std::to_string(faces.rows()) + "\nproperty list uchar int vertex_indices\nend_header\n";
    static_assert(Q_BYTE_ORDER == Q_LITTLE_ENDIAN, "the PLY writer stores native floats as little-endian");
    QByteArray body;
    body.reserve(qsizetype(header.size() + vertices * 28 + std::size_t(faces.rows()) * 13));
    body.append(header.data(), qsizetype(header.size()));
    for (std::size_t v = 0; v < vertices; ++v) {
        const float row[7] = {shape(Eigen::Index(v), 0), shape(Eigen::Index(v), 1), shape(Eigen::Index(v), 2),
            curvature.k1[v], curvature.k2[v], curvature.k1[v] * curvature.k2[v], curvature.gaussian[v]};
        body.append(reinterpret_cast<const char*>(row), sizeof(row));
    }
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        body.append(char(3));
        body.append(reinterpret_cast<const char*>(faces.row(f).data()), 12);
    }
    writeWholeFile(path, body); // whole or not at all; every write checked (issue 27)
}

} // namespace celform::model
