// The brushes' shared radius (brush_size.h).
#include "celform/views/tools/brush_size.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace celform::views {
namespace {

// The [ and ] keys' texts were the viewport's; their translations stay in its context.
struct Keys {
    Q_DECLARE_TR_FUNCTIONS(celform::views::Viewport)
};

} // namespace

void BrushSize::setRadius(double radius)
{
    if (!(radius > 0.0) || !std::isfinite(radius) || radius == m_radius)
        return;
    m_radius = radius;
    emit radiusChanged(radius);
}

void BrushSize::setPixelRadius(double pixels)
{
    if (!(pixels > 0.0) || !std::isfinite(pixels) || pixels == m_pixelRadius)
        return;
    m_pixelRadius = std::clamp(pixels, 1.0, 4096.0);
    emit pixelRadiusChanged(m_pixelRadius);
}

double BrushSize::worldRadius(double unitsPerPixel) const
{
    // A radius in pixels is the world radius that many pixels span at the point.
    return m_unit == Unit::Pixels ? m_pixelRadius * unitsPerPixel : m_radius;
}

double BrushSize::pixelsAt(double unitsPerPixel) const
{
    if (m_unit == Unit::Pixels)
        return m_pixelRadius;
    return unitsPerPixel > 0.0 ? m_radius / unitsPerPixel : 0.0;
}

void BrushSize::setCurrent(double value)
{
    if (m_unit == Unit::Pixels)
        setPixelRadius(value);
    else
        setRadius(value);
}

QString BrushSize::scale(double factor)
{
    setCurrent(current() * factor);
    if (m_unit == Unit::Pixels)
        return Keys::tr("Brush radius %1 px").arg(m_pixelRadius, 0, 'f', 0);
    return Keys::tr("Brush radius %1").arg(m_radius, 0, 'g', 3);
}

} // namespace celform::views
