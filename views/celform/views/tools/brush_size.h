// The brush radius the viewport's brushes share (the falloff brush, the shading-offset brush and
// the patch brush): in world units, or in widget pixels as Blender's "View" radius (the same size
// on screen whatever the zoom). The panels and the [ and ] keys set it, F-resize drags it.
#pragma once

#include <QObject>
#include <QString>

namespace celform::views {

class BrushSize : public QObject {
    Q_OBJECT
public:
    enum class Unit { World, Pixels };
    using QObject::QObject;

    /// Ignored unless positive and finite.
    void setRadius(double radius);
    [[nodiscard]] double radius() const { return m_radius; }
    /// Clamped to [1, 4096] pixels; ignored unless positive and finite.
    void setPixelRadius(double pixels);
    [[nodiscard]] double pixelRadius() const { return m_pixelRadius; }
    void setUnit(Unit unit) { m_unit = unit; }
    [[nodiscard]] Unit unit() const { return m_unit; }

    /// The world radius at a point where a pixel spans unitsPerPixel world units.
    [[nodiscard]] double worldRadius(double unitsPerPixel) const;
    /// The radius on screen there, in pixels (0 for a world radius without a scale).
    [[nodiscard]] double pixelsAt(double unitsPerPixel) const;
    /// The radius in the current unit: pixels or world units.
    [[nodiscard]] double current() const { return m_unit == Unit::Pixels ? m_pixelRadius : m_radius; }
    void setCurrent(double value);
    /// Scales the radius in the current unit (the [ and ] keys); returns what to tell the artist.
    QString scale(double factor);

signals:
    void radiusChanged(double radius);
    void pixelRadiusChanged(double pixels);

private:
    double m_radius = 0.1;
    double m_pixelRadius = 50.0;
    Unit m_unit = Unit::World;
};

} // namespace celform::views
