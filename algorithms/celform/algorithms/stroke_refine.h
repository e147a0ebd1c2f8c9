// Image-space clean-up of projected strokes, shared by the CPU renderer and the viewport so both
// draw the same lines (issue 25, "Lines without stray dashes"): ends closer than a gap joined,
// Chaikin smoothing, short strokes dropped, then overshoot, taper at the ends and Pencil+-style
// width reduction with depth.
#pragma once

#include "celform/algorithms/lines.h"
#include "celform/algorithms/ridge_snakes.h"

#include <array>
#include <vector>

namespace celform::algo {

/// Joins open strokes of the same class (outline or inner) whose ends lie at most
/// style.joinGap pixels apart at similar depth (within 2 %), closest pairs first, preferring
/// the straighter continuation. Closed strokes are left alone.
void joinStrokeGaps(std::vector<StyledStroke>& strokes, float gap);

/// Where strokes touch: an open stroke's end within tolerance pixels of a point of another stroke
/// (a junction of three or more feature edges, or a line meeting an outline) is not free, and
/// the point it touches is pinned. Taper thins free ends only and smoothing keeps pinned points,
/// so lines that meet in the picture stay joined.
struct StrokeContacts {
    std::vector<std::array<bool, 2>> freeEnds; ///< per stroke: head, tail
    std::vector<std::vector<char>> pinned; ///< per stroke and point
};
StrokeContacts findStrokeContacts(const std::vector<StyledStroke>& strokes, float tolerance);

/// Chaikin's corner cutting (Chaikin 1974), `rounds` times: each segment is replaced by its
/// points at 1/4 and 3/4. Stroke ends and corners sharper than 60 degrees stay where they are, so
/// a cube's silhouette keeps its corners. Depths and widths are interpolated alike.
/// pinned (optional, as findStrokeContacts gives it) keeps more points.
void smoothStrokes(
    std::vector<StyledStroke>& strokes, int rounds, const std::vector<std::vector<char>>* pinned = nullptr);
constexpr int kMaxSmoothing = 4; ///< more rounds are clamped to this

/// Length of a stroke's polyline in pixels.
float strokeLength(const StyledStroke& stroke);

/// Drops strokes shorter than minPixels; contacts (optional) lose the same entries.
void dropShortStrokes(std::vector<StyledStroke>& strokes, float minPixels, StrokeContacts* contacts = nullptr);

/// Narrows open strokes towards their ends over `length` pixels (at most half the stroke) down
/// to kTaperTip of their width, with a smoothstep profile, as a pen pressed and lifted.
/// freeEnds (optional, findStrokeContacts): only these ends narrow.
void taperStrokes(
    std::vector<StyledStroke>& strokes, float length, const std::vector<std::array<bool, 2>>* freeEnds = nullptr);
constexpr float kTaperTip = 0.2f;

/// Pencil+ 4's "reduction": widths scale by 1 - reduction * t, t = 0 at the nearest stroke point
/// of the picture and 1 at the farthest (linear in camera depth).
void reduceWidthWithDepth(std::vector<StyledStroke>& strokes, float reduction);

/// All of the above in order, with the style's settings, for a picture imageHeight pixels high:
/// join, find the contacts, smooth, drop short strokes (style.minLength * imageHeight),
/// overshoot, taper the free ends, reduce.
void refineStrokes(std::vector<StyledStroke>& strokes, const LineStyle& style, int imageHeight);

/// The stroke path of a picture, one function for the renderer and the viewport: the chained
/// strokes (and apparent-ridge snakes, may be null) projected with project(point) -> (x, y,
/// depth), styled, then refined for an image imageHeight pixels high.
template <typename Project>
std::vector<StyledStroke> pictureStrokes(const std::vector<Stroke>& strokes, const RidgeSnakes* snakes,
    const Positions& shape, const LineStyle& style, int imageHeight, Project project)
{
    LineStyle raw = style;
    raw.overshoot = 0.0f; // after joining, so joined ends do not overshoot into each other
    std::vector<StyledStroke> styled = styleStrokes(strokes, shape, raw, project);
    if (snakes && !snakes->strokes.empty()) {
        std::vector<StyledStroke> ridges = styleSnakes(*snakes, raw, project);
        styled.reserve(styled.size() + ridges.size());
        for (StyledStroke& r : ridges)
            styled.push_back(std::move(r));
    }
    refineStrokes(styled, style, imageHeight);
    return styled;
}

} // namespace celform::algo
