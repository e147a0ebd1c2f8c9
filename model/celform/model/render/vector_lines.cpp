// A frame's lines as geometry (vector_lines.h).
#include "celform/model/render/vector_lines.h"

#include "celform/algorithms/region_outline.h"
#include "celform/algorithms/stroke_visibility.h"

#include <algorithm>
#include <cmath>

namespace celform::model {
namespace {

/// The tone regions of one eye: each covered pixel goes to the nearest level of the ramp.
std::vector<VectorTone> toneRegions(const algo::RenderPasses& passes, const algo::ToonRamp& ramp)
{
    std::vector<float> levels = ramp.intensities;
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    const int width = passes.beauty.width, height = passes.beauty.height;
    const std::size_t count = std::size_t(width) * std::size_t(height);
    if (levels.empty() || passes.tone.size() != count || passes.id.size() != count)
        return {};
    std::vector<int> label(count, -1);
    for (std::size_t i = 0; i < count; ++i) {
        if (passes.id[i] < 0)
            continue;
        const auto nearest = std::min_element(levels.begin(), levels.end(),
            [&](float a, float b) { return std::abs(a - passes.tone[i]) < std::abs(b - passes.tone[i]); });
        label[i] = int(nearest - levels.begin());
    }
    std::vector<VectorTone> out;
    std::vector<char> mask(count);
    for (std::size_t l = 0; l < levels.size(); ++l) {
        // The colour away from the lines (the beauty has them drawn in), else over all its pixels.
        Eigen::Vector3d clear = Eigen::Vector3d::Zero(), all = Eigen::Vector3d::Zero();
        std::size_t clearCount = 0, allCount = 0;
        for (std::size_t i = 0; i < count; ++i) {
            mask[i] = label[i] == int(l);
            if (!mask[i])
                continue;
            const float* p = passes.beauty.pixels.data() + 4 * i;
            const Eigen::Vector3d c(p[0], p[1], p[2]);
            all += c;
            ++allCount;
            if (passes.lines.size() == count && passes.lines[i] < 0.01f) {
                clear += c;
                ++clearCount;
            }
        }
        if (allCount == 0)
            continue;
        VectorTone tone;
        tone.level = levels[l];
        tone.color = (clearCount > 0 ? clear / double(clearCount) : all / double(allCount)).cast<float>();
        tone.outlines = algo::traceRegionOutlines(mask, width, height);
        out.push_back(std::move(tone));
    }
    return out;
}

} // namespace

VectorLines vectorLinesOf(
    const std::vector<algo::RenderPasses>& eyes, algo::StereoOutput stereo, const Look& look, bool tones, int frame)
{
    VectorLines out;
    out.stereo = stereo;
    out.frame = frame;
    out.lineColor = look.lineStyle.color;
    if (eyes.empty())
        return out;
    out.width = eyes.front().beauty.width;
    out.height = eyes.front().beauty.height;
    for (std::size_t e = 0; e < eyes.size(); ++e) {
        const algo::RenderPasses& passes = eyes[e];
        VectorLinesEye eye;
        eye.name = eyes.size() == 1 ? QStringLiteral("mono")
            : e == 0                ? QStringLiteral("left")
                                    : QStringLiteral("right");
        eye.strokes = algo::visibleStrokeParts(
            passes.strokes, passes.depth, passes.id, passes.beauty.width, passes.beauty.height);
        if (tones)
            eye.tones = toneRegions(passes, look.toon);
        out.eyes.push_back(std::move(eye));
    }
    return out;
}

QByteArray decimalText(double v, int decimals)
{
    if (!std::isfinite(v))
        return "null";
    const double scale = std::pow(10.0, decimals);
    QByteArray s = QByteArray::number(std::round(v * scale) / scale, 'f', decimals);
    if (s.contains('.')) {
        while (s.endsWith('0'))
            s.chop(1);
        if (s.endsWith('.'))
            s.chop(1);
    }
    return s == "-0" ? QByteArray("0") : s;
}

const std::vector<std::uint8_t>& lineKindOrder()
{
    static const std::vector<std::uint8_t> order
        = {algo::kSilhouette, algo::kBorder, algo::kCrease, algo::kMaterialBoundary, algo::kRidge};
    return order;
}

std::uint8_t primaryLineKind(std::uint8_t kinds)
{
    for (const std::uint8_t k : lineKindOrder())
        if (kinds & k)
            return k;
    return algo::kCrease;
}

QString lineKindName(std::uint8_t kind)
{
    switch (kind) {
    case algo::kSilhouette:
        return QStringLiteral("silhouette");
    case algo::kCrease:
        return QStringLiteral("crease");
    case algo::kBorder:
        return QStringLiteral("border");
    case algo::kMaterialBoundary:
        return QStringLiteral("material");
    case algo::kRidge:
        return QStringLiteral("ridge");
    default:
        return QStringLiteral("line");
    }
}

} // namespace celform::model
