// Stereo camera pairs (paper 3, section 3.1) and the anaglyph / side-by-side compositions
// (paper 3, section 4.5.2) of the offline renderer.
#include "celform/algorithms/stereo.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace celform::algo {

namespace {

/// Rotation of `point` about the axis through `pivot` along unit `axis`.
Eigen::Vector3d rotateAbout(
    const Eigen::Vector3d& point, const Eigen::Vector3d& pivot, const Eigen::Vector3d& axis, double angle)
{
    return pivot + Eigen::AngleAxisd(angle, axis) * (point - pivot);
}

bool sameSize(const ImageRGBA& a, const ImageRGBA& b)
{
    return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size()
        && a.pixels.size() == std::size_t(std::max(0, a.width)) * std::size_t(std::max(0, a.height)) * 4;
}

/// Per pixel out = combine(left rgba, right rgba); empty image when the sizes differ.
template <typename Combine> ImageRGBA composePixels(const ImageRGBA& left, const ImageRGBA& right, Combine combine)
{
    if (!sameSize(left, right))
        return {};
    ImageRGBA out(left.width, left.height);
    for (std::size_t i = 0; i < out.pixels.size(); i += 4)
        combine(left.pixels.data() + i, right.pixels.data() + i, out.pixels.data() + i);
    return out;
}

void copyInto(const ImageRGBA& source, ImageRGBA& target, int x0, int y0)
{
    for (int y = 0; y < source.height; ++y)
        std::copy_n(source.at(0, y), std::size_t(source.width) * 4, target.at(x0, y0 + y));
}

} // namespace

std::pair<RasterCamera, RasterCamera> stereoPair(const RasterCamera& centre, const StereoSettings& settings)
{
    assert(settings.convergence > 0.0);
    RasterCamera left = centre;
    RasterCamera right = centre;
    const double b = 0.5 * settings.interocular;
    const Eigen::Vector3d forward = centre.forward();
    const Eigen::Vector3d side = centre.right();
    const bool converge = settings.convergence > 0.0 && std::isfinite(settings.convergence);
    const Eigen::Vector3d convergencePoint = centre.eye + settings.convergence * forward;

    if (centre.orthographic) {
        // Parallel orthographic eyes see every depth with the same offset, so shifting them
        // gives no depth at all. Instead each eye's view is turned by atan(b / C) about the up
        // axis through the convergence point (toe-in, paper 3, section 3.1): the left eye looks
        // slightly to the right. Disparity is then linear in depth and zero at the convergence
        // plane, with the same signs as the perspective pair. (toeIn makes no difference here.)
        if (converge) {
            const double angle = std::atan(b / settings.convergence);
            const Eigen::Vector3d axis = centre.trueUp();
            // A positive turn about up carries -forward towards +right: the left eye turns by -angle.
            left.eye = rotateAbout(centre.eye, convergencePoint, axis, -angle);
            right.eye = rotateAbout(centre.eye, convergencePoint, axis, angle);
            left.target = right.target = convergencePoint;
        }
    } else if (settings.toeIn) {
        // Toe-in (paper 3, section 3.1): eyes moved sideways, each turned to the convergence
        // point. Simple, but it skews verticals (vertical disparity away from the centre).
        left.eye = centre.eye - b * side;
        right.eye = centre.eye + b * side;
        if (converge)
            left.target = right.target = convergencePoint;
        else {
            left.target = left.eye + forward;
            right.target = right.eye + forward;
        }
    } else {
        // Off-axis (paper 3, section 3.1, fig. 3.2): parallel eyes at -/+ b along right, frusta
        // shifted towards each other. A point at depth D has p.right larger by b for the left eye
        // than for the centre, so x_left = x_centre + f b / D + s_left w; zero disparity at D = C
        // needs s_left = -f b / (C w) and s_right = +f b / (C w). Then
        //   x_right - x_left = 2 f b (1 / C - 1 / D):
        // negative (crossed: x_left > x_right) in front of the convergence plane, positive
        // (uncrossed) behind it, tending to 2 f b / C at infinity.
        left.eye = centre.eye - b * side;
        right.eye = centre.eye + b * side;
        left.target = centre.target - b * side;
        right.target = centre.target + b * side;
        if (converge && centre.width > 0) {
            const double focal
                = 0.5 * centre.height / std::tan(0.5 * centre.fovYDegrees * 3.14159265358979323846 / 180.0);
            const double shift = focal * b / (settings.convergence * centre.width);
            left.horizontalShift = centre.horizontalShift - shift;
            right.horizontalShift = centre.horizontalShift + shift;
        }
    }
    if (settings.swapEyes)
        std::swap(left, right);
    return {left, right};
}

DuboisMatrices DuboisMatrices::redCyan()
{
    // Dubois' least-squares red/cyan projection (E. Dubois, "A projection method to generate
    // anaglyph stereo images", ICASSP 2001), the widely used red-cyan coefficients.
    DuboisMatrices m;
    m.left << 0.437f, 0.449f, 0.164f, //
        -0.062f, -0.062f, -0.024f, //
        -0.048f, -0.050f, -0.017f;
    m.right << -0.011f, -0.032f, -0.007f, //
        0.377f, 0.761f, 0.009f, //
        -0.026f, -0.093f, 1.234f;
    return m;
}

ImageRGBA composeAnaglyph(const ImageRGBA& left, const ImageRGBA& right)
{
    // Paper 3, section 4.5.2: left * (1, 0, 0) + right * (0, 1, 1).
    return composePixels(left, right, [](const float* l, const float* r, float* o) {
        o[0] = l[0];
        o[1] = r[1];
        o[2] = r[2];
        o[3] = std::max(l[3], r[3]);
    });
}

ImageRGBA composeDubois(const ImageRGBA& left, const ImageRGBA& right, const DuboisMatrices& m)
{
    return composePixels(left, right, [&m](const float* l, const float* r, float* o) {
        const Eigen::Vector3f c
            = m.left * Eigen::Vector3f(l[0], l[1], l[2]) + m.right * Eigen::Vector3f(r[0], r[1], r[2]);
        for (int k = 0; k < 3; ++k)
            o[k] = std::clamp(c[k], 0.f, 1.f);
        o[3] = std::max(l[3], r[3]);
    });
}

ImageRGBA composeHalfColor(const ImageRGBA& left, const ImageRGBA& right)
{
    return composePixels(left, right, [](const float* l, const float* r, float* o) {
        // Rec. 709 / sRGB luminance weights on linear light.
        o[0] = 0.2126f * l[0] + 0.7152f * l[1] + 0.0722f * l[2];
        o[1] = r[1];
        o[2] = r[2];
        o[3] = std::max(l[3], r[3]);
    });
}

ImageRGBA composeSideBySide(const ImageRGBA& left, const ImageRGBA& right)
{
    if (!sameSize(left, right))
        return {};
    ImageRGBA out(left.width * 2, left.height);
    copyInto(left, out, 0, 0);
    copyInto(right, out, left.width, 0);
    return out;
}

ImageRGBA composeTopBottom(const ImageRGBA& left, const ImageRGBA& right)
{
    if (!sameSize(left, right))
        return {};
    ImageRGBA out(left.width, left.height * 2);
    copyInto(left, out, 0, 0);
    copyInto(right, out, 0, left.height);
    return out;
}

} // namespace celform::algo
