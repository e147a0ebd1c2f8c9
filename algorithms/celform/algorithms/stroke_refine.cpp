// Image-space clean-up of projected strokes (issue 25, "Lines without stray dashes").
#include "celform/algorithms/stroke_refine.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

namespace celform::algo {
namespace {

constexpr std::uint8_t kOutlineClass = kSilhouette | kBorder;
/// Ends at different depths are different lines even when they meet in the picture.
constexpr float kJoinDepthTolerance = 0.02f;
/// Chaikin keeps points whose polyline turns by more than 60 degrees (cos 60 = 0.5).
constexpr float kCornerCosine = 0.5f;

bool isOutline(const StyledStroke& s)
{
    return (s.kinds & kOutlineClass) != 0;
}

/// Unit direction leaving stroke s at its head (head = true) or tail, from its first
/// non-degenerate segment; zero when the stroke has no length.
Eigen::Vector2f outward(const StyledStroke& s, bool head)
{
    const std::size_t m = s.points.size();
    const Eigen::Vector2f& end = head ? s.points.front() : s.points.back();
    for (std::size_t k = 1; k < m; ++k) {
        const Eigen::Vector2f d = end - s.points[head ? k : m - 1 - k];
        const float len = d.norm();
        if (len > 0.0f)
            return d / len;
    }
    return Eigen::Vector2f::Zero();
}

std::size_t findRoot(std::vector<std::size_t>& parent, std::size_t i)
{
    while (parent[i] != i)
        i = parent[i] = parent[parent[i]];
    return i;
}

/// Appends stroke s to out, reversed when reverse is set, without repeating a shared point.
void appendStroke(StyledStroke& out, const StyledStroke& s, bool reverse)
{
    const std::size_t m = s.points.size();
    for (std::size_t k = 0; k < m; ++k) {
        const std::size_t i = reverse ? m - 1 - k : k;
        if (k == 0 && !out.points.empty() && out.points.back() == s.points[i])
            continue;
        out.points.push_back(s.points[i]);
        out.depths.push_back(s.depths[i]);
        out.widths.push_back(s.widths[i]);
    }
    out.kinds |= s.kinds;
}

/// One round of Chaikin's corner cutting; fixed points are kept and stay fixed.
void chaikinRound(StyledStroke& s, std::vector<char>& fixed, bool cyclic)
{
    const std::size_t m = s.points.size();
    StyledStroke out;
    out.kinds = s.kinds;
    out.closed = s.closed;
    std::vector<char> outFixed;
    const std::size_t reserve = 2 * m + 2;
    out.points.reserve(reserve);
    out.depths.reserve(reserve);
    out.widths.reserve(reserve);
    outFixed.reserve(reserve);
    auto emit = [&](std::size_t a, std::size_t b, float t, bool isFixed) {
        out.points.push_back((1.0f - t) * s.points[a] + t * s.points[b]);
        out.depths.push_back((1.0f - t) * s.depths[a] + t * s.depths[b]);
        out.widths.push_back((1.0f - t) * s.widths[a] + t * s.widths[b]);
        outFixed.push_back(char(isFixed));
    };
    const std::size_t segments = cyclic ? m : m - 1;
    for (std::size_t i = 0; i < m; ++i) {
        if (fixed[i])
            emit(i, i, 0.0f, true);
        if (i < segments) {
            const std::size_t j = (i + 1) % m;
            emit(i, j, 0.25f, false);
            emit(i, j, 0.75f, false);
        }
    }
    s.points.swap(out.points);
    s.depths.swap(out.depths);
    s.widths.swap(out.widths);
    fixed.swap(outFixed);
}

} // namespace

void joinStrokeGaps(std::vector<StyledStroke>& strokes, float gap)
{
    if (!(gap > 0.0f) || strokes.size() < 2)
        return;
    const std::size_t n = strokes.size();
    // End e of stroke e / 2: its head when e is even, its tail when odd.
    auto usable = [&](std::size_t i) { return !strokes[i].closed && strokes[i].points.size() >= 2; };
    auto point = [&](std::size_t e) -> const Eigen::Vector2f& {
        const StyledStroke& s = strokes[e / 2];
        return (e & 1) ? s.points.back() : s.points.front();
    };
    auto depth = [&](std::size_t e) {
        const StyledStroke& s = strokes[e / 2];
        return (e & 1) ? s.depths.back() : s.depths.front();
    };
    std::vector<std::size_t> ends;
    for (std::size_t i = 0; i < n; ++i)
        if (usable(i)) {
            ends.push_back(2 * i);
            ends.push_back(2 * i + 1);
        }
    // Sweep over ends sorted by x: candidate pairs lie within gap in x.
    std::sort(ends.begin(), ends.end(), [&](std::size_t a, std::size_t b) {
        return std::make_pair(point(a).x(), a) < std::make_pair(point(b).x(), b);
    });
    struct Candidate {
        float cost;
        std::size_t a, b;
    };
    std::vector<Candidate> candidates;
    for (std::size_t i = 0; i < ends.size(); ++i) {
        const std::size_t a = ends[i];
        for (std::size_t k = i + 1; k < ends.size() && point(ends[k]).x() - point(a).x() <= gap; ++k) {
            const std::size_t b = ends[k];
            if (a / 2 == b / 2 || isOutline(strokes[a / 2]) != isOutline(strokes[b / 2]))
                continue;
            const float dist = (point(a) - point(b)).norm();
            const float da = depth(a), db = depth(b);
            if (dist > gap || std::abs(da - db) > kJoinDepthTolerance * std::max(da, db))
                continue;
            // Continuing straight on: the two outward directions are opposite. No hairpins.
            const float straight = -outward(strokes[a / 2], !(a & 1)).dot(outward(strokes[b / 2], !(b & 1)));
            if (straight < -0.5f)
                continue;
            candidates.push_back({dist + 0.5f * (1.0f - straight), std::min(a, b), std::max(a, b)});
        }
    }
    if (candidates.empty())
        return;
    std::sort(candidates.begin(), candidates.end(),
        [](const Candidate& x, const Candidate& y) { return std::tie(x.cost, x.a, x.b) < std::tie(y.cost, y.a, y.b); });
    constexpr std::size_t kFree = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> link(2 * n, kFree);
    std::vector<std::size_t> parent(n);
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    for (const Candidate& c : candidates) {
        if (link[c.a] != kFree || link[c.b] != kFree)
            continue;
        const std::size_t ra = findRoot(parent, c.a / 2), rb = findRoot(parent, c.b / 2);
        if (ra == rb)
            continue; // would close a loop
        parent[ra] = rb;
        link[c.a] = c.b;
        link[c.b] = c.a;
    }
    // Walk each chain from a free end; chains are ordered by the smallest stroke index met first.
    std::vector<char> done(n, 0);
    std::vector<StyledStroke> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (done[i])
            continue;
        if (!usable(i) || (link[2 * i] == kFree && link[2 * i + 1] == kFree)) {
            done[i] = 1;
            out.push_back(std::move(strokes[i]));
            continue;
        }
        // Back to the chain's free end through the heads' side.
        std::size_t entry = 2 * i; // the end we enter stroke entry / 2 by
        while (link[entry] != kFree)
            entry = link[entry] ^ 1;
        StyledStroke joined;
        joined.kinds = 0;
        for (;;) {
            const std::size_t s = entry / 2;
            done[s] = 1;
            appendStroke(joined, strokes[s], (entry & 1) != 0);
            const std::size_t exit = entry ^ 1;
            if (link[exit] == kFree)
                break;
            entry = link[exit];
        }
        out.push_back(std::move(joined));
    }
    strokes.swap(out);
}

void smoothStrokes(std::vector<StyledStroke>& strokes, int rounds, const std::vector<std::vector<char>>* pinned)
{
    if (rounds <= 0)
        return;
    rounds = std::min(rounds, kMaxSmoothing); // each round doubles the points
    std::vector<char> fixed;
    for (std::size_t index = 0; index < strokes.size(); ++index) {
        StyledStroke& s = strokes[index];
        const bool cyclic = s.closed && s.points.size() >= 4;
        if (cyclic) { // the repeated first point goes, and comes back after smoothing
            s.points.pop_back();
            s.depths.pop_back();
            s.widths.pop_back();
        }
        const std::size_t m = s.points.size();
        if (m < 3) {
            if (cyclic) {
                s.points.push_back(s.points.front());
                s.depths.push_back(s.depths.front());
                s.widths.push_back(s.widths.front());
            }
            continue;
        }
        fixed.assign(m, 0);
        if (pinned && index < pinned->size())
            for (std::size_t i = 0; i < m && i < (*pinned)[index].size(); ++i)
                fixed[i] = (*pinned)[index][i];
        if (!cyclic)
            fixed.front() = fixed.back() = 1;
        for (std::size_t i = 0; i < m; ++i) {
            if (!cyclic && (i == 0 || i + 1 == m))
                continue;
            const Eigen::Vector2f in = s.points[i] - s.points[(i + m - 1) % m];
            const Eigen::Vector2f next = s.points[(i + 1) % m] - s.points[i];
            const float lengths = in.norm() * next.norm();
            if (!fixed[i] && lengths > 0.0f && in.dot(next) < kCornerCosine * lengths)
                fixed[i] = 1;
        }
        for (int r = 0; r < rounds; ++r)
            chaikinRound(s, fixed, cyclic);
        if (cyclic) {
            s.points.push_back(s.points.front());
            s.depths.push_back(s.depths.front());
            s.widths.push_back(s.widths.front());
        }
    }
}

float strokeLength(const StyledStroke& stroke)
{
    float length = 0.0f;
    for (std::size_t k = 1; k < stroke.points.size(); ++k)
        length += (stroke.points[k] - stroke.points[k - 1]).norm();
    return length;
}

void dropShortStrokes(std::vector<StyledStroke>& strokes, float minPixels, StrokeContacts* contacts)
{
    if (!(minPixels > 0.0f))
        return;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < strokes.size(); ++i) {
        if (strokeLength(strokes[i]) < minPixels)
            continue;
        if (kept != i) {
            strokes[kept] = std::move(strokes[i]);
            if (contacts) {
                contacts->freeEnds[kept] = contacts->freeEnds[i];
                contacts->pinned[kept] = std::move(contacts->pinned[i]);
            }
        }
        ++kept;
    }
    strokes.resize(kept);
    if (contacts) {
        contacts->freeEnds.resize(kept);
        contacts->pinned.resize(kept);
    }
}

void taperStrokes(std::vector<StyledStroke>& strokes, float length, const std::vector<std::array<bool, 2>>* freeEnds)
{
    if (!(length > 0.0f))
        return;
    std::vector<float> along;
    for (std::size_t index = 0; index < strokes.size(); ++index) {
        StyledStroke& s = strokes[index];
        const std::size_t m = s.points.size();
        if (s.closed || m < 2)
            continue;
        const bool headFree = !freeEnds || index >= freeEnds->size() || (*freeEnds)[index][0];
        const bool tailFree = !freeEnds || index >= freeEnds->size() || (*freeEnds)[index][1];
        if (!headFree && !tailFree)
            continue;
        along.assign(m, 0.0f);
        for (std::size_t k = 1; k < m; ++k)
            along[k] = along[k - 1] + (s.points[k] - s.points[k - 1]).norm();
        const float total = along.back();
        // Both ends free: each ramp takes at most half the stroke; one free: all of it.
        const float ramp = std::min(length, headFree && tailFree ? 0.5f * total : total);
        if (!(ramp > 0.0f))
            continue;
        const float far = std::numeric_limits<float>::infinity();
        for (std::size_t k = 0; k < m; ++k) {
            const float d = std::min(headFree ? along[k] : far, tailFree ? total - along[k] : far);
            if (d >= ramp)
                continue;
            const float t = d / ramp;
            s.widths[k] *= kTaperTip + (1.0f - kTaperTip) * t * t * (3.0f - 2.0f * t);
        }
    }
}

void reduceWidthWithDepth(std::vector<StyledStroke>& strokes, float reduction)
{
    if (!(reduction > 0.0f))
        return;
    float near = std::numeric_limits<float>::infinity(), far = -near;
    for (const StyledStroke& s : strokes)
        for (const float d : s.depths)
            if (std::isfinite(d)) {
                near = std::min(near, d);
                far = std::max(far, d);
            }
    if (!(far > near))
        return;
    const float k = std::min(reduction, 1.0f) / (far - near);
    for (StyledStroke& s : strokes)
        for (std::size_t i = 0; i < s.widths.size(); ++i)
            if (std::isfinite(s.depths[i]))
                s.widths[i] *= 1.0f - k * (s.depths[i] - near);
}

StrokeContacts findStrokeContacts(const std::vector<StyledStroke>& strokes, float tolerance)
{
    StrokeContacts c;
    c.freeEnds.assign(strokes.size(), {true, true});
    c.pinned.resize(strokes.size());
    for (std::size_t i = 0; i < strokes.size(); ++i)
        c.pinned[i].assign(strokes[i].points.size(), 0);
    const float cell = std::max(tolerance, 0.5f);
    // Every point in a grid of cells `cell` wide, sorted by cell: (cell key, stroke, point).
    struct Entry {
        std::int64_t key;
        std::uint32_t stroke, point;
    };
    // Unsigned bits: a negative cell shifted left is undefined in C++17.
    auto keyOf = [&](std::int64_t cx, std::int64_t cy) {
        return std::int64_t((std::uint64_t(cx) << 32) ^ (std::uint64_t(cy) & 0xffffffffULL));
    };
    // Clamped first: a point projected from near the eye may lie far beyond any int64 cell.
    auto cellOf = [&](float v) { return std::int64_t(std::floor(std::clamp(v / cell, -1e9f, 1e9f))); };
    std::vector<Entry> grid;
    for (std::size_t i = 0; i < strokes.size(); ++i)
        for (std::size_t k = 0; k < strokes[i].points.size(); ++k) {
            const Eigen::Vector2f& p = strokes[i].points[k];
            if (std::isfinite(p.x()) && std::isfinite(p.y()))
                grid.push_back({keyOf(cellOf(p.x()), cellOf(p.y())), std::uint32_t(i), std::uint32_t(k)});
        }
    std::sort(grid.begin(), grid.end(), [](const Entry& a, const Entry& b) {
        return std::tie(a.key, a.stroke, a.point) < std::tie(b.key, b.stroke, b.point);
    });
    const float tolerance2 = tolerance * tolerance;
    for (std::size_t i = 0; i < strokes.size(); ++i) {
        const StyledStroke& s = strokes[i];
        const std::size_t m = s.points.size();
        if (s.closed || m < 2)
            continue;
        for (int end = 0; end < 2; ++end) {
            const std::size_t at = end == 0 ? 0 : m - 1;
            const Eigen::Vector2f& p = s.points[at];
            if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
                continue;
            const std::int64_t cx = cellOf(p.x()), cy = cellOf(p.y());
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dx = -1; dx <= 1; ++dx) {
                    const std::int64_t key = keyOf(cx + dx, cy + dy);
                    auto it = std::lower_bound(
                        grid.begin(), grid.end(), key, [](const Entry& e, std::int64_t k) { return e.key < k; });
                    for (; it != grid.end() && it->key == key; ++it) {
                        // Its own neighbouring points do not count.
                        if (it->stroke == i && std::abs(std::int64_t(it->point) - std::int64_t(at)) <= 2)
                            continue;
                        if ((strokes[it->stroke].points[it->point] - p).squaredNorm() > tolerance2)
                            continue;
                        c.freeEnds[i][std::size_t(end)] = false;
                        c.pinned[it->stroke][it->point] = 1;
                    }
                }
        }
    }
    return c;
}

void refineStrokes(std::vector<StyledStroke>& strokes, const LineStyle& style, int imageHeight)
{
    joinStrokeGaps(strokes, style.joinGap);
    // Junctions: a line ending on another stays attached (no taper there, and the point it
    // touches is not smoothed away).
    StrokeContacts contacts = findStrokeContacts(strokes, std::max(style.joinGap, 1.0f));
    smoothStrokes(strokes, style.smoothing, &contacts.pinned);
    dropShortStrokes(strokes, style.minLength * float(std::max(imageHeight, 0)), &contacts);
    for (StyledStroke& s : strokes)
        overshootEnds(s, style.overshoot);
    taperStrokes(strokes, style.taper, &contacts.freeEnds);
    reduceWidthWithDepth(strokes, style.reduction);
}

} // namespace celform::algo
