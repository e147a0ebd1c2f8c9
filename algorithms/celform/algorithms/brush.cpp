// The falloff brush of paper 1, section 3.1.2 and the hashed uniform grid that finds its
// selection without scanning the mesh.
#include "celform/algorithms/brush.h"

#include "celform/algorithms/symmetry.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>

namespace celform::algo {

namespace {

// Cell coordinates are packed 21 bits per axis into one 64-bit key.
constexpr int kKeyBits = 21;
constexpr std::int64_t kMaxCellCoord = (std::int64_t(1) << kKeyBits) - 2;
constexpr std::uint64_t kEmptyKey = ~std::uint64_t(0);
// Target for the expected number of vertices sharing a vertex's cell: a query then scans few
// cells and few vertices outside the sphere.
constexpr double kTargetOccupancy = 16.0;

std::uint64_t packKey(std::int64_t x, std::int64_t y, std::int64_t z)
{
    return std::uint64_t(x) | (std::uint64_t(y) << kKeyBits) | (std::uint64_t(z) << (2 * kKeyBits));
}

Eigen::Array3i unpackKey(std::uint64_t key)
{
    constexpr std::uint64_t mask = (std::uint64_t(1) << kKeyBits) - 1;
    return {int(key & mask), int((key >> kKeyBits) & mask), int((key >> (2 * kKeyBits)) & mask)};
}

std::uint64_t mixHash(std::uint64_t key)
{
    // splitmix64 finaliser: neighbouring cells land far apart in the table.
    key ^= key >> 30;
    key *= 0xbf58476d1ce4e5b9ULL;
    key ^= key >> 27;
    key *= 0x94d049bb133111ebULL;
    key ^= key >> 31;
    return key;
}

/// Open-addressing (linear probing) map from cell key to dense cell id.
class CellTable {
public:
    void reset(std::size_t expected)
    {
        std::size_t capacity = 64;
        while (capacity < 2 * expected)
            capacity *= 2;
        m_keys.assign(capacity, kEmptyKey);
        m_ids.assign(capacity, 0);
        m_mask = capacity - 1;
        m_size = 0;
    }
    /// Id of key, inserting it with id = size() when absent.
    std::uint32_t findOrInsert(std::uint64_t key)
    {
        if (2 * (m_size + 1) > m_keys.size())
            grow();
        std::size_t slot = mixHash(key) & m_mask;
        while (m_keys[slot] != kEmptyKey) {
            if (m_keys[slot] == key)
                return m_ids[slot];
            slot = (slot + 1) & m_mask;
        }
        m_keys[slot] = key;
        m_ids[slot] = std::uint32_t(m_size);
        return std::uint32_t(m_size++);
    }
    /// Id of key, or -1.
    std::int64_t find(std::uint64_t key) const
    {
        std::size_t slot = mixHash(key) & m_mask;
        while (m_keys[slot] != kEmptyKey) {
            if (m_keys[slot] == key)
                return m_ids[slot];
            slot = (slot + 1) & m_mask;
        }
        return -1;
    }
    [[nodiscard]] std::size_t size() const { return m_size; }

private:
    void grow()
    {
        std::vector<std::uint64_t> keys;
        std::vector<std::uint32_t> ids;
        keys.swap(m_keys);
        ids.swap(m_ids);
        m_keys.assign(keys.size() * 2, kEmptyKey);
        m_ids.assign(keys.size() * 2, 0);
        m_mask = m_keys.size() - 1;
        for (std::size_t i = 0; i < keys.size(); ++i) {
            if (keys[i] == kEmptyKey)
                continue;
            std::size_t slot = mixHash(keys[i]) & m_mask;
            while (m_keys[slot] != kEmptyKey)
                slot = (slot + 1) & m_mask;
            m_keys[slot] = keys[i];
            m_ids[slot] = ids[i];
        }
    }

    std::vector<std::uint64_t> m_keys;
    std::vector<std::uint32_t> m_ids;
    std::size_t m_mask = 0;
    std::size_t m_size = 0;
};

bool isFinite(const Positions& v, Eigen::Index i)
{
    return std::isfinite(v(i, 0)) && std::isfinite(v(i, 1)) && std::isfinite(v(i, 2));
}

} // namespace

struct VertexGrid::Data {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    double cellSize = 1.0;
    Eigen::Array3i minCell = Eigen::Array3i::Zero(); ///< bounds of the occupied cells
    Eigen::Array3i maxCell = Eigen::Array3i::Zero();
    CellTable table;
    std::vector<std::uint64_t> cellKeys; ///< per cell id
    std::vector<std::uint32_t> cellStart; ///< per cell id + 1, into order/points
    std::vector<std::uint32_t> order; ///< vertex indices grouped by cell, ascending in a cell
    std::vector<Eigen::Vector3f> points; ///< positions in the same order, for cache-friendly scans

    [[nodiscard]] Eigen::Array3i cellOf(const Eigen::Vector3d& p) const
    {
        const Eigen::Array3d c = ((p - origin) / cellSize).array().floor();
        const Eigen::Array3d lo = Eigen::Array3d::Constant(-1.0),
                             hi = Eigen::Array3d::Constant(double(kMaxCellCoord) + 1);
        return c.max(lo).min(hi).cast<int>();
    }

    /// Calls visit(cellId) for every occupied cell overlapping the sphere (centre, radius).
    template <typename Visit> void forCellsNear(const Eigen::Vector3d& centre, double radius, Visit&& visit) const
    {
        const Eigen::Array3i lo = cellOf(centre - Eigen::Vector3d::Constant(radius)).max(minCell);
        const Eigen::Array3i hi = cellOf(centre + Eigen::Vector3d::Constant(radius)).min(maxCell);
        if ((hi < lo).any())
            return;
        const double r2 = radius * radius;
        const auto overlaps = [&](const Eigen::Array3i& c) {
            // Squared distance from centre to the cell's box.
            const Eigen::Array3d boxMin = origin.array() + c.cast<double>() * cellSize;
            const Eigen::Array3d d = (boxMin - centre.array()).max(centre.array() - (boxMin + cellSize)).max(0.0);
            return d.matrix().squaredNorm() <= r2;
        };
        const Eigen::Array3d span = (hi - lo + 1).cast<double>();
        if (span.prod() > double(cellKeys.size())) {
            // A query box larger than the occupied set: walk the occupied cells instead, so the
            // cost never exceeds one pass over the cells.
            for (std::size_t id = 0; id < cellKeys.size(); ++id) {
                const Eigen::Array3i c = unpackKey(cellKeys[id]);
                if ((c >= lo).all() && (c <= hi).all() && overlaps(c))
                    visit(std::uint32_t(id));
            }
            return;
        }
        for (int z = lo.z(); z <= hi.z(); ++z)
            for (int y = lo.y(); y <= hi.y(); ++y)
                for (int x = lo.x(); x <= hi.x(); ++x) {
                    const std::int64_t id = table.find(packKey(x, y, z));
                    if (id >= 0 && overlaps({x, y, z}))
                        visit(std::uint32_t(id));
                }
    }
};

VertexGrid::VertexGrid(const Positions& vertices, double cellSize)
{
    auto data = std::make_shared<Data>();
    const Eigen::Index n = vertices.rows();
    Eigen::AlignedBox3d box;
    for (Eigen::Index i = 0; i < n; ++i)
        if (isFinite(vertices, i))
            box.extend(vertices.row(i).transpose().cast<double>());
    if (box.isEmpty()) {
        m = data; // no finite vertex: every query answers nothing
        return;
    }
    const Eigen::Vector3d extent = box.sizes();
    // Keys hold 21 bits per axis; never let a cell be smaller than that allows.
    const double minCell = std::max(extent.maxCoeff() / double(kMaxCellCoord - 1), 1e-30);
    data->origin = box.min();

    const auto countCells = [&](double size, std::vector<std::uint32_t>& cellOfVertex) {
        data->cellSize = size;
        data->table.reset(std::min<std::size_t>(std::size_t(n), 1u << 16));
        data->cellKeys.clear();
        cellOfVertex.assign(std::size_t(n), std::numeric_limits<std::uint32_t>::max());
        std::vector<std::uint32_t> counts;
        // Mesh files tend to list neighbouring vertices together: reuse the last cell's id.
        std::uint64_t lastKey = kEmptyKey;
        std::uint32_t lastId = 0;
        for (Eigen::Index i = 0; i < n; ++i) {
            if (!isFinite(vertices, i))
                continue;
            const Eigen::Array3i c = data->cellOf(vertices.row(i).transpose().cast<double>());
            const std::uint64_t key = packKey(c.x(), c.y(), c.z());
            const std::uint32_t id = key == lastKey ? lastId : data->table.findOrInsert(key);
            lastKey = key;
            lastId = id;
            if (id == counts.size()) {
                counts.push_back(0);
                data->cellKeys.push_back(key);
            }
            ++counts[id];
            cellOfVertex[std::size_t(i)] = id;
        }
        return counts;
    };

    std::vector<std::uint32_t> cellOfVertex;
    std::vector<std::uint32_t> counts;
    if (cellSize > 0.0) {
        counts = countCells(std::max(cellSize, minCell), cellOfVertex);
    } else {
        // Start from the cell size that would give about one vertex per cell if the vertices
        // filled the bounding box (degenerate axes ignored), then shrink while a vertex shares its
        // cell with too many others: surfaces fill only a thin shell of the box, and a few far
        // outliers must not put the whole mesh into one cell.
        std::size_t finite = 0;
        for (Eigen::Index i = 0; i < n; ++i)
            finite += isFinite(vertices, i) ? 1 : 0;
        const double diag = std::max(extent.norm(), 1e-30);
        double volume = 1.0;
        int dims = 0;
        for (int a = 0; a < 3; ++a)
            if (extent[a] > 1e-9 * diag) {
                volume *= extent[a];
                ++dims;
            }
        double size = dims == 0 ? diag : std::pow(volume / double(finite), 1.0 / dims);
        size = std::max(size, minCell);
        for (int attempt = 0;; ++attempt) {
            counts = countCells(size, cellOfVertex);
            double occupancy = 0.0; // expected number of vertices in the cell of a random vertex
            for (const std::uint32_t c : counts)
                occupancy += double(c) * double(c);
            occupancy /= double(finite);
            if (occupancy <= 2.0 * kTargetOccupancy || attempt == 3 || size <= minCell)
                break;
            // Occupancy grows with the square of the cell size on a surface.
            size = std::max(minCell, size * std::max(0.125, std::sqrt(kTargetOccupancy / occupancy)));
        }
    }

    // Counting sort by cell; iterating vertices in index order keeps each cell ascending.
    const std::size_t cells = counts.size();
    data->cellStart.assign(cells + 1, 0);
    for (std::size_t c = 0; c < cells; ++c)
        data->cellStart[c + 1] = data->cellStart[c] + counts[c];
    std::vector<std::uint32_t> fill(data->cellStart.begin(), data->cellStart.end() - 1);
    data->order.resize(data->cellStart.back());
    data->points.resize(data->cellStart.back());
    for (Eigen::Index i = 0; i < n; ++i) {
        const std::uint32_t c = cellOfVertex[std::size_t(i)];
        if (c == std::numeric_limits<std::uint32_t>::max())
            continue;
        const std::uint32_t slot = fill[c]++;
        data->order[slot] = std::uint32_t(i);
        data->points[slot] = vertices.row(i).transpose();
    }
    data->minCell = Eigen::Array3i::Constant(std::numeric_limits<int>::max());
    data->maxCell = Eigen::Array3i::Constant(std::numeric_limits<int>::min());
    for (const std::uint64_t key : data->cellKeys) {
        data->minCell = data->minCell.min(unpackKey(key));
        data->maxCell = data->maxCell.max(unpackKey(key));
    }
    m = data;
}

bool VertexGrid::empty() const
{
    return !m || m->order.empty();
}

void VertexGrid::radiusQuery(const Eigen::Vector3d& centre, double radius, std::vector<std::uint32_t>& indices,
    std::vector<float>& distances) const
{
    indices.clear();
    distances.clear();
    if (empty() || !(radius >= 0.0) || !centre.allFinite())
        return;
    const double r2 = radius * radius;
    // (index, squared distance) pairs, sorted by index at the end: cells come out in grid order.
    std::vector<std::pair<std::uint32_t, double>> found;
    m->forCellsNear(centre, radius, [&](std::uint32_t cell) {
        for (std::uint32_t k = m->cellStart[cell]; k < m->cellStart[cell + 1]; ++k) {
            const double d2 = (m->points[k].cast<double>() - centre).squaredNorm();
            if (d2 <= r2)
                found.emplace_back(m->order[k], d2);
        }
    });
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    indices.reserve(found.size());
    distances.reserve(found.size());
    for (const auto& [index, d2] : found) {
        indices.push_back(index);
        distances.push_back(float(std::sqrt(d2)));
    }
}

std::int64_t VertexGrid::nearest(const Eigen::Vector3d& point, double maxDistance) const
{
    if (empty() || !point.allFinite() || !(maxDistance >= 0.0))
        return -1;
    // Search spheres of doubling radius: once the best candidate lies within the searched radius,
    // nothing outside can be nearer. The bounding-box distance caps the radius for far points.
    const Eigen::Vector3d boxMin = m->origin + m->minCell.cast<double>().matrix() * m->cellSize;
    const Eigen::Vector3d boxMax = m->origin + (m->maxCell + 1).cast<double>().matrix() * m->cellSize;
    const double farthest = (point - boxMin).cwiseAbs().cwiseMax((point - boxMax).cwiseAbs()).norm();
    const double limit = std::min(maxDistance, farthest);
    double radius = std::min(limit, m->cellSize);
    for (;;) {
        std::int64_t best = -1;
        double bestD2 = radius * radius;
        m->forCellsNear(point, radius, [&](std::uint32_t cell) {
            for (std::uint32_t k = m->cellStart[cell]; k < m->cellStart[cell + 1]; ++k) {
                const double d2 = (m->points[k].cast<double>() - point).squaredNorm();
                // Ties go to the lower index so that the answer does not depend on cell order.
                if (d2 < bestD2 || (d2 == bestD2 && (best < 0 || m->order[k] < best))) {
                    bestD2 = d2;
                    best = m->order[k];
                }
            }
        });
        if (best >= 0 || radius >= limit)
            return best;
        radius = std::min(limit, radius * 2.0);
    }
}

BrushSelection selectForBrush(
    const Positions& shape, const VertexGrid& grid, std::uint32_t picked, double radius, const BrushProfile& profile)
{
    const double strength = std::isfinite(profile.strength) ? std::clamp(profile.strength, 0.0, 1.0) : 1.0;
    assert(Eigen::Index(picked) < shape.rows());
    BrushSelection selection;
    selection.picked = picked;
    selection.radius = std::max(radius, 0.0);
    const Eigen::Vector3d centre = shape.row(picked).transpose().cast<double>();
    std::vector<float> distances;
    grid.radiusQuery(centre, selection.radius, selection.indices, distances);
    // Paper 1, section 3.1.2: weight (1 - d/r)^2 with d the 3D distance to the picked vertex.
    // Vertices at exactly r get weight 0 and are dropped; the picked vertex is always in with 1.
    std::size_t kept = 0;
    bool hasPicked = false;
    selection.weights.resize(selection.indices.size());
    for (std::size_t k = 0; k < selection.indices.size(); ++k) {
        const std::uint32_t v = selection.indices[k];
        const double w
            = strength * (v == picked ? 1.0 : brushFalloff(double(distances[k]), selection.radius, profile.falloff));
        if (w <= 0.0)
            continue;
        hasPicked = hasPicked || v == picked;
        selection.indices[kept] = v;
        selection.weights[kept] = float(w);
        ++kept;
    }
    selection.indices.resize(kept);
    selection.weights.resize(kept);
    if (!hasPicked) { // grid built on another shape, or radius 0
        const auto at = std::lower_bound(selection.indices.begin(), selection.indices.end(), picked);
        const auto offset = at - selection.indices.begin();
        selection.indices.insert(at, picked);
        selection.weights.insert(selection.weights.begin() + offset, float(strength));
    }
    return selection;
}

namespace {

void assertOrthonormal(const ImageFrame& frame)
{
    (void)frame;
    assert(std::abs(frame.right.norm() - 1.0) < 1e-6 && std::abs(frame.up.norm() - 1.0) < 1e-6
        && std::abs(frame.forward.norm() - 1.0) < 1e-6);
    assert(std::abs(frame.right.dot(frame.up)) < 1e-6 && std::abs(frame.right.dot(frame.forward)) < 1e-6
        && std::abs(frame.up.dot(frame.forward)) < 1e-6);
}

/// Displacements (into out, #selection by 3) from an in-plane map of (right, up) offsets relative
/// to the picked vertex.
template <typename InPlane>
void inPlaneEdit(
    const BrushSelection& selection, const Positions& shape, const ImageFrame& frame, InPlane&& map, Positions& out)
{
    assertOrthonormal(frame);
    assert(Eigen::Index(selection.picked) < shape.rows());
    const Eigen::Vector3d pivot = shape.row(selection.picked).transpose().cast<double>();
    out.resize(Eigen::Index(selection.indices.size()), 3);
    for (std::size_t k = 0; k < selection.indices.size(); ++k) {
        const Eigen::Vector3d q = shape.row(selection.indices[k]).transpose().cast<double>() - pivot;
        const Eigen::Vector2d ab(q.dot(frame.right), q.dot(frame.up));
        const Eigen::Vector2d moved = map(ab, double(selection.weights[k]));
        // Only right and up components change: the forward (depth) component is kept.
        const Eigen::Vector3d d = (moved.x() - ab.x()) * frame.right + (moved.y() - ab.y()) * frame.up;
        out.row(Eigen::Index(k)) = d.transpose().cast<float>();
    }
}

/// Each selected vertex moved by its falloff weight times move.
void weightedMove(const BrushSelection& selection, const Eigen::Vector3d& move, Positions& out)
{
    out.resize(Eigen::Index(selection.indices.size()), 3);
    for (std::size_t k = 0; k < selection.indices.size(); ++k)
        out.row(Eigen::Index(k)) = (double(selection.weights[k]) * move).transpose().cast<float>();
}

} // namespace

void brushDrag(const BrushSelection& selection, const ImageFrame& frame, double dx, double dy, Positions& out)
{
    assertOrthonormal(frame);
    // Paper 1, section 3.1.2: every selected vertex follows the drag scaled by its falloff, in the
    // image plane, so the Z distance from the camera stays unchanged.
    weightedMove(selection, dx * frame.right + dy * frame.up, out);
}

Positions brushDrag(const BrushSelection& selection, const ImageFrame& frame, double dx, double dy)
{
    Positions out;
    brushDrag(selection, frame, dx, dy, out);
    return out;
}

void brushPush(const BrushSelection& selection, const ImageFrame& frame, double dz, Positions& out)
{
    assertOrthonormal(frame);
    // Paper 1, section 3.1.2: push and pull along the view direction, same falloff.
    weightedMove(selection, dz * frame.forward, out);
}

Positions brushPush(const BrushSelection& selection, const ImageFrame& frame, double dz)
{
    Positions out;
    brushPush(selection, frame, dz, out);
    return out;
}

void brushRotate(
    const BrushSelection& selection, const Positions& shape, const ImageFrame& frame, double angle, Positions& out)
{
    // Paper 1, section 3.1.2 (suggested rotations): in screen coordinates (a, b) = (right, up) a
    // positive angle turns right toward up.
    inPlaneEdit(
        selection, shape, frame,
        [angle](const Eigen::Vector2d& ab, double w) {
            const double c = std::cos(angle * w), s = std::sin(angle * w);
            return Eigen::Vector2d(c * ab.x() - s * ab.y(), s * ab.x() + c * ab.y());
        },
        out);
}

Positions brushRotate(const BrushSelection& selection, const Positions& shape, const ImageFrame& frame, double angle)
{
    Positions out;
    brushRotate(selection, shape, frame, angle, out);
    return out;
}

void brushScale(
    const BrushSelection& selection, const Positions& shape, const ImageFrame& frame, double factor, Positions& out)
{
    // Paper 1, section 3.1.2 (suggested scalings), blended by the falloff weight.
    inPlaneEdit(
        selection, shape, frame,
        [factor](const Eigen::Vector2d& ab, double w) { return Eigen::Vector2d((1.0 + (factor - 1.0) * w) * ab); },
        out);
}

Positions brushScale(const BrushSelection& selection, const Positions& shape, const ImageFrame& frame, double factor)
{
    Positions out;
    brushScale(selection, shape, frame, factor, out);
    return out;
}

void brushSmooth(const BrushSelection& selection, const Positions& shape, const Faces& faces, const VertexFaces& around,
    double strength, Positions& out, std::vector<std::int32_t>& scratch, bool tangential)
{
    assert(around.start.size() == std::size_t(shape.rows()) + 1);
    out.resize(Eigen::Index(selection.indices.size()), 3);
    for (std::size_t k = 0; k < selection.indices.size(); ++k) {
        const std::uint32_t v = selection.indices[k];
        // The one ring from the faces around v: the two other corners of each face, distinct.
        scratch.clear();
        for (auto i = around.start[v]; i < around.start[v + 1]; ++i) {
            const std::int32_t f = around.faces[std::size_t(i)];
            for (int c = 0; c < 3; ++c)
                if (faces(f, c) != std::int32_t(v))
                    scratch.push_back(faces(f, c));
        }
        std::sort(scratch.begin(), scratch.end());
        scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
        if (scratch.empty()) {
            out.row(Eigen::Index(k)).setZero();
            continue;
        }
        Eigen::Vector3d average = Eigen::Vector3d::Zero();
        for (const std::int32_t n : scratch)
            average += shape.row(n).transpose().cast<double>();
        average /= double(scratch.size());
        const Eigen::Vector3d p = shape.row(v).transpose().cast<double>();
        Eigen::Vector3d move = average - p;
        if (tangential) {
            // Twice the area-weighted normal: the sum of the faces' cross products.
            Eigen::Vector3d normal = Eigen::Vector3d::Zero();
            for (auto i = around.start[v]; i < around.start[v + 1]; ++i) {
                const std::int32_t f = around.faces[std::size_t(i)];
                const Eigen::Vector3d a = shape.row(faces(f, 0)).transpose().cast<double>();
                const Eigen::Vector3d b = shape.row(faces(f, 1)).transpose().cast<double>();
                const Eigen::Vector3d c = shape.row(faces(f, 2)).transpose().cast<double>();
                normal += (b - a).cross(c - a);
            }
            if (normal.squaredNorm() > 0.0) {
                normal.normalize();
                move -= move.dot(normal) * normal;
            }
        }
        out.row(Eigen::Index(k)) = (strength * double(selection.weights[k]) * move).transpose().cast<float>();
    }
}

Positions brushSmooth(const BrushSelection& selection, const Positions& shape, const Faces& faces, double strength)
{
    const std::size_t count = selection.indices.size();
    Positions delta = Positions::Zero(Eigen::Index(count), 3);
    if (count == 0)
        return delta;
    // Slot of each vertex in the selection (or -1). Indices are ascending, so a range check
    // rejects most corners of a large mesh before the table is read.
    const std::uint32_t lo = selection.indices.front(), hi = selection.indices.back();
    std::vector<std::int32_t> slot(std::size_t(hi - lo) + 1, -1);
    for (std::size_t k = 0; k < count; ++k)
        slot[selection.indices[k] - lo] = std::int32_t(k);
    const auto slotOf = [&](std::int32_t v) {
        return (v < std::int32_t(lo) || v > std::int32_t(hi)) ? -1 : slot[std::size_t(v) - lo];
    };

    // One-ring adjacency of the selected vertices only, in compressed rows (2 entries per corner).
    std::vector<std::int32_t> touching;
    std::vector<std::uint32_t> start(count + 1, 0);
    for (Eigen::Index f = 0; f < faces.rows(); ++f) {
        bool any = false;
        for (int c = 0; c < 3; ++c) {
            const std::int32_t s = slotOf(faces(f, c));
            if (s >= 0) {
                start[std::size_t(s) + 1] += 2;
                any = true;
            }
        }
        if (any)
            touching.push_back(std::int32_t(f));
    }
    for (std::size_t k = 0; k < count; ++k)
        start[k + 1] += start[k];
    std::vector<std::int32_t> ring(start.back());
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (const std::int32_t f : touching)
        for (int c = 0; c < 3; ++c) {
            const std::int32_t s = slotOf(faces(f, c));
            if (s < 0)
                continue;
            ring[fill[std::size_t(s)]++] = faces(f, (c + 1) % 3);
            ring[fill[std::size_t(s)]++] = faces(f, (c + 2) % 3);
        }

    for (std::size_t k = 0; k < count; ++k) {
        // Each interior neighbour appears twice (two faces share the edge): average the distinct ones.
        auto first = ring.begin() + start[k], last = ring.begin() + start[k + 1];
        std::sort(first, last);
        last = std::unique(first, last);
        if (first == last)
            continue;
        Eigen::Vector3d average = Eigen::Vector3d::Zero();
        for (auto it = first; it != last; ++it)
            average += shape.row(*it).transpose().cast<double>();
        average /= double(last - first);
        const Eigen::Vector3d p = shape.row(selection.indices[k]).transpose().cast<double>();
        delta.row(Eigen::Index(k))
            = (strength * double(selection.weights[k]) * (average - p)).transpose().cast<float>();
    }
    return delta;
}

std::vector<std::int32_t> mirrorMap(const Positions& base, double tolerance)
{
    return mirrorMap(base, AxisPlane{0, 0.0}, tolerance);
}

} // namespace celform::algo
