// Colour swatches of the look panels: the document stores linear RGB, screens show sRGB.
#pragma once

#include "celform/algorithms/image.h"

#include <Eigen/Core>
#include <QColor>

#include <algorithm>
#include <cmath>

namespace celform::views {

/// A linear colour as the renderer writes it to an 8-bit file (sRGB-encoded).
inline QColor toQColor(const Eigen::Vector3f& linear)
{
    auto encode = [](float v) { return int(std::lround(255.f * algo::linearToSrgb(std::clamp(v, 0.f, 1.f)))); };
    return QColor(encode(linear.x()), encode(linear.y()), encode(linear.z()));
}

/// The linear colour of a picked sRGB colour.
inline Eigen::Vector3f fromQColor(const QColor& c)
{
    return {algo::srgbToLinear(float(c.redF())), algo::srgbToLinear(float(c.greenF())),
        algo::srgbToLinear(float(c.blueF()))};
}

} // namespace celform::views
