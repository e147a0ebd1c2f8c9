// Shape blending (paper 1, section 3.2.3): out = base + sum w'_i * offset_i. Memory-bound, so
// everything is one pass over cache-sized blocks of vertices: each array is streamed once.
#include "celform/algorithms/blend.h"

#include <Eigen/LU>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>

namespace celform::algo {

namespace {

// Plain float loops over 3 * #V values with restrict pointers: GCC vectorizes them (blend.cpp is
// compiled with the dynamic vectorizer cost model, see algorithms/CMakeLists.txt). The sum is
// always base + w1*o1 + w2*o2 + ... in that order, so weight 1 gives base + offset exactly.

void fused1(float* __restrict out, const float* __restrict base, const float* __restrict o1, float w1, std::size_t n)
{
    for (std::size_t i = 0; i < n; ++i)
        out[i] = base[i] + w1 * o1[i];
}

void fused2(float* __restrict out, const float* __restrict base, const float* __restrict o1, const float* __restrict o2,
    float w1, float w2, std::size_t n)
{
    for (std::size_t i = 0; i < n; ++i)
        out[i] = base[i] + w1 * o1[i] + w2 * o2[i];
}

void fused3(float* __restrict out, const float* __restrict base, const float* __restrict o1, const float* __restrict o2,
    const float* __restrict o3, float w1, float w2, float w3, std::size_t n)
{
    for (std::size_t i = 0; i < n; ++i)
        out[i] = base[i] + w1 * o1[i] + w2 * o2[i] + w3 * o3[i];
}

void fused4(float* __restrict out, const float* __restrict base, const float* __restrict o1, const float* __restrict o2,
    const float* __restrict o3, const float* __restrict o4, float w1, float w2, float w3, float w4, std::size_t n)
{
    for (std::size_t i = 0; i < n; ++i)
        out[i] = base[i] + w1 * o1[i] + w2 * o2[i] + w3 * o3[i] + w4 * o4[i];
}

/// out[0, n) = src + sum of up to four weighted dense arrays, read from element first on. src may
/// equal out (fifth and further dense keys): that case avoids the restrict versions.
void fusedPass(
    float* out, const float* src, const WeightedOffsets* const* keys, int count, std::size_t first, std::size_t n)
{
    const float* o[4] = {nullptr, nullptr, nullptr, nullptr};
    float w[4] = {0.f, 0.f, 0.f, 0.f};
    for (int k = 0; k < count; ++k) {
        o[k] = keys[k]->offsets.offsets + first;
        w[k] = keys[k]->weight;
    }
    if (src == out) {
        // In place (a fifth and further dense key): out[i] += ..., still one streaming pass.
        for (std::size_t i = 0; i < n; ++i) {
            float v = out[i];
            for (int k = 0; k < count; ++k)
                v += w[k] * o[k][i];
            out[i] = v;
        }
        return;
    }
    switch (count) {
    case 0:
        std::memcpy(out, src, n * sizeof(float));
        break;
    case 1:
        fused1(out, src, o[0], w[0], n);
        break;
    case 2:
        fused2(out, src, o[0], o[1], w[0], w[1], n);
        break;
    case 3:
        fused3(out, src, o[0], o[1], o[2], w[0], w[1], w[2], n);
        break;
    default:
        fused4(out, src, o[0], o[1], o[2], o[3], w[0], w[1], w[2], w[3], n);
        break;
    }
}

} // namespace

void blendShape(const Positions& base, const std::vector<WeightedOffsets>& keys, Positions& out)
{
    const Eigen::Index vertexCount = base.rows();
    out.resize(vertexCount, 3);
    assert(out.data() != base.data() || vertexCount == 0);
    const std::size_t n = static_cast<std::size_t>(vertexCount) * 3;
    if (n == 0)
        return;

    std::vector<const WeightedOffsets*> dense;
    std::vector<const WeightedOffsets*> sparse;
    for (const WeightedOffsets& k : keys) {
        if (k.weight == 0.f || k.offsets.count == 0)
            continue;
        assert(k.offsets.offsets != nullptr);
        if (k.offsets.dense) {
            assert(k.offsets.count == static_cast<std::size_t>(vertexCount));
            dense.push_back(&k);
        } else {
            assert(k.offsets.indices != nullptr);
            sparse.push_back(&k);
        }
    }

    // Paper 1, section 3.2.3: v = base + sum w'_i * offset_i, vertex by vertex. One pass over
    // blocks of vertices small enough to stay in L1: the dense keys are fused (four at a time)
    // reading base and each offset array once, then the sparse keys' entries that fall in the
    // block are scatter-added while the block is still cached. out is written once.
    constexpr std::size_t kBlockVertices = 1024;
    std::vector<std::size_t> cursor(sparse.size(), 0);
    float* dst = out.data();
    const std::size_t vertices = static_cast<std::size_t>(vertexCount);
    for (std::size_t first = 0; first < vertices; first += kBlockVertices) {
        const std::size_t last = std::min(vertices, first + kBlockVertices);
        const std::size_t offset = 3 * first;
        const std::size_t len = 3 * (last - first);
        const float* src = base.data() + offset;
        std::size_t done = 0;
        do {
            const int count = static_cast<int>(std::min<std::size_t>(4, dense.size() - done));
            fusedPass(dst + offset, src, dense.data() + done, count, offset, len);
            done += static_cast<std::size_t>(count);
            src = dst + offset;
        } while (done < dense.size());

        for (std::size_t k = 0; k < sparse.size(); ++k) {
            const std::uint32_t* idx = sparse[k]->offsets.indices;
            const float* off = sparse[k]->offsets.offsets;
            const float w = sparse[k]->weight;
            const std::size_t count = sparse[k]->offsets.count;
            std::size_t j = cursor[k];
            for (; j < count && idx[j] < last; ++j) {
                assert(idx[j] >= first); // strictly increasing indices
                float* v = dst + 3 * static_cast<std::size_t>(idx[j]);
                v[0] += w * off[3 * j];
                v[1] += w * off[3 * j + 1];
                v[2] += w * off[3 * j + 2];
            }
            cursor[k] = j;
        }
    }
#ifndef NDEBUG
    for (std::size_t k = 0; k < sparse.size(); ++k)
        assert(cursor[k] == sparse[k]->offsets.count); // every index < #V
#endif
}

} // namespace celform::algo

namespace celform::algo {

std::vector<double> splineWeights(const std::vector<double>& knots, double t, bool periodic)
{
    const auto n = Eigen::Index(knots.size());
    std::vector<double> w(knots.size(), 0.0);
    if (n == 0)
        return w;
    if (n == 1 || (periodic && n < 3)) {
        w[0] = 1.0;
        return w;
    }
    if (periodic) {
        const double period = knots.back() - knots.front();
        t = knots.front() + std::fmod(t - knots.front(), period);
        if (t < knots.front())
            t += period;
    } else if (t <= knots.front() || t >= knots.back()) {
        w[t <= knots.front() ? 0 : std::size_t(n - 1)] = 1.0;
        return w;
    }
    // The interval [knots[k], knots[k + 1]) holding t; exactly at a knot, that knot alone.
    const auto upper = std::upper_bound(knots.begin(), knots.end(), t);
    const auto k = Eigen::Index(std::max<std::ptrdiff_t>(upper - knots.begin() - 1, 0));
    const auto wrapped = [&](Eigen::Index i) { return periodic && i == n - 1 ? Eigen::Index(0) : i; };
    if (t == knots[std::size_t(k)]) {
        w[std::size_t(wrapped(k))] = 1.0;
        return w;
    }
    // Second derivatives M = R y (Press et al., "Numerical Recipes", 3.3): for each inner knot i
    // h[i-1] M[i-1] + 2 (h[i-1] + h[i]) M[i] + h[i] M[i+1] = 6 ((y[i+1] - y[i]) / h[i] - (y[i] - y[i-1]) / h[i-1]).
    // Natural ends: M = 0 at both. Periodic: the equations run round the cycle of m = n - 1 knots.
    const Eigen::Index m = periodic ? n - 1 : n;
    std::vector<double> h(std::size_t(n - 1));
    for (Eigen::Index i = 0; i + 1 < n; ++i)
        h[std::size_t(i)] = knots[std::size_t(i + 1)] - knots[std::size_t(i)];
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, m), d = Eigen::MatrixXd::Zero(m, m);
    for (Eigen::Index i = 0; i < m; ++i) {
        if (!periodic && (i == 0 || i == n - 1)) {
            a(i, i) = 1.0;
            continue;
        }
        const Eigen::Index prev = (i + m - 1) % m, next = (i + 1) % m;
        const double hp = h[std::size_t(periodic ? (i + m - 1) % m : i - 1)], hn = h[std::size_t(i)];
        a(i, prev) += hp;
        a(i, i) += 2.0 * (hp + hn);
        a(i, next) += hn;
        d(i, next) += 6.0 / hn;
        d(i, i) -= 6.0 / hn + 6.0 / hp;
        d(i, prev) += 6.0 / hp;
    }
    const Eigen::MatrixXd r = a.partialPivLu().solve(d); // M = r * y
    const double hk = h[std::size_t(k)];
    const double a0 = (knots[std::size_t(k + 1)] - t) / hk, b0 = 1.0 - a0;
    const double c0 = (a0 * a0 * a0 - a0) * hk * hk / 6.0, c1 = (b0 * b0 * b0 - b0) * hk * hk / 6.0;
    const Eigen::Index k0 = wrapped(k), k1 = wrapped(k + 1);
    w[std::size_t(k0)] += a0;
    w[std::size_t(k1)] += b0;
    for (Eigen::Index j = 0; j < m; ++j)
        w[std::size_t(j)] += c0 * r(k0, j) + c1 * r(k1, j);
    return w;
}

} // namespace celform::algo
