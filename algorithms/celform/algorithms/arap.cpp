// As-rigid-as-possible deformation on Eigen's sparse LDL^T (arap.h).
#include "celform/algorithms/arap.h"

#include <Eigen/LU>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>

namespace celform::algo {

namespace {

/// The rotation R maximising trace(R S) for the covariance S = sum w e e'^T (rest spokes e,
/// current e'): R = V U^T for S = U Sigma V^T, a reflection turned into the nearest rotation by
/// flipping the axis of the smallest singular value. Found through the closed-form eigenvectors
/// of S^T S (V, Sigma^2) and U = S V / Sigma, several times faster than a Jacobi SVD; falls back
/// to the SVD when the spokes are nearly collinear (two singular values vanish).
Eigen::Matrix3d bestRotation(const Eigen::Matrix3d& s)
{
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
    eigen.computeDirect(s.transpose() * s);
    const Eigen::Vector3d lambda = eigen.eigenvalues(); // ascending
    const Eigen::Matrix3d v = eigen.eigenvectors();
    if (eigen.info() == Eigen::Success && lambda(2) > 0.0 && lambda(1) > 1e-12 * lambda(2)) {
        const Eigen::Vector3d u2 = (s * v.col(2)).normalized();
        Eigen::Vector3d u1 = s * v.col(1);
        u1 = (u1 - u1.dot(u2) * u2).normalized();
        Eigen::Matrix3d u;
        u.col(2) = u2;
        u.col(1) = u1;
        // det(U) = det(V) makes V U^T a rotation: the smallest axis follows the other two.
        u.col(0) = (v.determinant() > 0.0 ? 1.0 : -1.0) * u1.cross(u2);
        const Eigen::Matrix3d r = v * u.transpose();
        if (r.allFinite())
            return r;
    }
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(s, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d u = svd.matrixU();
    Eigen::Matrix3d r = svd.matrixV() * u.transpose();
    if (r.determinant() < 0.0) {
        u.col(2) = -u.col(2);
        r = svd.matrixV() * u.transpose();
    }
    return r;
}

} // namespace

struct ArapSolver::Data {
    Eigen::MatrixXd rest; ///< #V by 3
    std::vector<std::int32_t> freeIndex; ///< per vertex: row in the system, or -1
    std::vector<std::int32_t> freeVertex; ///< per row: its vertex
    /// Spokes in compressed rows: the neighbours of vertex v are neighbour[start[v] .. start[v+1]),
    /// with their symmetric cotangent weights.
    std::vector<std::int32_t> start;
    std::vector<std::int32_t> neighbour;
    std::vector<double> weight;
    std::vector<double> degree; ///< sum of the spokes' weights per vertex
    Eigen::SparseMatrix<double> laplacian; ///< free rows and columns, handles excluded
    Eigen::SparseMatrix<double> system; ///< laplacian + handle stiffness on the diagonal
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
    bool analysed = false;
    std::vector<double> handleStiffness; ///< per free row
    Eigen::MatrixXd handleTarget; ///< per free row, 3 columns
};

ArapSolver::ArapSolver(const Positions& rest, const Faces& faces, const std::vector<std::uint8_t>& free)
    : m(std::make_unique<Data>())
{
    const Eigen::Index n = rest.rows();
    m->rest = rest.cast<double>();
    // Cotangent weights (Sorkine and Alexa, equation 3 with w_ij = (cot a + cot b) / 2), clamped
    // to a small positive value: obtuse triangles would make the system indefinite.
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(std::size_t(faces.rows()) * 6);
    double sum = 0.0;
    std::int64_t count = 0;
    for (Eigen::Index f = 0; f < faces.rows(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int i = faces(f, k), j = faces(f, (k + 1) % 3), o = faces(f, (k + 2) % 3);
            if (i < 0 || j < 0 || o < 0 || i >= n || j >= n || o >= n)
                continue;
            const Eigen::Vector3d a = m->rest.row(i) - m->rest.row(o), b = m->rest.row(j) - m->rest.row(o);
            const double cross = a.cross(b).norm();
            const double cot = cross > 1e-20 ? a.dot(b) / cross : 0.0;
            triplets.emplace_back(i, j, 0.5 * cot);
            triplets.emplace_back(j, i, 0.5 * cot);
            sum += std::abs(cot);
            ++count;
        }
    Eigen::SparseMatrix<double, Eigen::RowMajor> w(n, n);
    w.setFromTriplets(triplets.begin(), triplets.end());
    const double floor = 1e-3 * (count > 0 ? 0.5 * sum / double(count) : 1.0);
    m->start.assign(std::size_t(n) + 1, 0);
    m->degree.assign(std::size_t(n), 0.0);
    for (Eigen::Index v = 0; v < n; ++v) {
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(w, v); it; ++it) {
            if (it.col() == v)
                continue;
            const double wij = std::max(it.value(), floor);
            m->neighbour.push_back(std::int32_t(it.col()));
            m->weight.push_back(wij);
            m->degree[std::size_t(v)] += wij;
        }
        m->start[std::size_t(v) + 1] = std::int32_t(m->neighbour.size());
    }
    m->freeIndex.assign(std::size_t(n), -1);
    for (Eigen::Index v = 0; v < n; ++v)
        if (std::size_t(v) < free.size() && free[std::size_t(v)] && m->degree[std::size_t(v)] > 0.0) {
            m->freeIndex[std::size_t(v)] = std::int32_t(m->freeVertex.size());
            m->freeVertex.push_back(std::int32_t(v));
        }
    const Eigen::Index rows = Eigen::Index(m->freeVertex.size());
    triplets.clear();
    for (Eigen::Index r = 0; r < rows; ++r) {
        const std::int32_t v = m->freeVertex[std::size_t(r)];
        triplets.emplace_back(r, r, m->degree[std::size_t(v)]);
        for (std::int32_t k = m->start[std::size_t(v)]; k < m->start[std::size_t(v) + 1]; ++k) {
            const std::int32_t c = m->freeIndex[std::size_t(m->neighbour[std::size_t(k)])];
            if (c >= 0)
                triplets.emplace_back(r, c, -m->weight[std::size_t(k)]);
        }
    }
    m->laplacian.resize(rows, rows);
    m->laplacian.setFromTriplets(triplets.begin(), triplets.end());
    m->laplacian.makeCompressed();
    m->handleStiffness.assign(std::size_t(rows), 0.0);
    m->handleTarget = Eigen::MatrixXd::Zero(rows, 3);
}

ArapSolver::~ArapSolver() = default;

std::int64_t ArapSolver::freeCount() const
{
    return std::int64_t(m->freeVertex.size());
}

bool ArapSolver::setHandles(const std::vector<ArapHandle>& handles)
{
    std::fill(m->handleStiffness.begin(), m->handleStiffness.end(), 0.0);
    m->handleTarget.setZero();
    for (const ArapHandle& h : handles) {
        if (h.vertex < 0 || std::size_t(h.vertex) >= m->freeIndex.size())
            continue;
        const std::int32_t r = m->freeIndex[std::size_t(h.vertex)];
        if (r < 0 || !(h.stiffness > 0.0))
            continue;
        const double k = h.stiffness * m->degree[std::size_t(h.vertex)];
        m->handleStiffness[std::size_t(r)] += k;
        m->handleTarget.row(r) += k * h.target.transpose();
    }
    for (std::size_t r = 0; r < m->handleStiffness.size(); ++r)
        if (m->handleStiffness[r] > 0.0)
            m->handleTarget.row(Eigen::Index(r)) /= m->handleStiffness[r];
    // A tiny pull of every free vertex towards where it is keeps parts without handles or fixed
    // neighbours (a loose eye, an island of the region) from making the system singular.
    m->system = m->laplacian;
    for (Eigen::Index r = 0; r < m->system.rows(); ++r)
        m->system.coeffRef(r, r)
            += m->handleStiffness[std::size_t(r)] + 1e-6 * m->degree[std::size_t(m->freeVertex[std::size_t(r)])];
    // The pattern never changes (the diagonal is always there): analyse it once, refactorise only.
    if (!m->analysed) {
        m->solver.analyzePattern(m->system);
        m->analysed = true;
    }
    m->solver.factorize(m->system);
    return m->solver.info() == Eigen::Success;
}

bool ArapSolver::solve(Eigen::MatrixXd& current, int iterations, const Progress* progress)
{
    const Eigen::Index n = m->rest.rows();
    if (current.rows() != n || current.cols() != 3)
        return true;
    for (Eigen::Index v = 0; v < n; ++v)
        if (m->freeIndex[std::size_t(v)] < 0)
            current.row(v) = m->rest.row(v);
    const Eigen::Index rows = Eigen::Index(m->freeVertex.size());
    if (rows == 0)
        return true;
    std::vector<Eigen::Matrix3d> rotation(std::size_t(n), Eigen::Matrix3d::Identity());
    Eigen::MatrixXd rhs(rows, 3);
    for (int it = 0; it < iterations; ++it) {
        if (cancelRequested(progress))
            return false;
        // Local step: the rotation that best maps each vertex's rest spokes onto its current ones
        // (Sorkine and Alexa, section 2.1: the polar part of the covariance, by SVD).
        for (Eigen::Index v = 0; v < n; ++v) {
            Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
            for (std::int32_t k = m->start[std::size_t(v)]; k < m->start[std::size_t(v) + 1]; ++k) {
                const std::int32_t j = m->neighbour[std::size_t(k)];
                const Eigen::Vector3d e0 = (m->rest.row(v) - m->rest.row(j)).transpose();
                const Eigen::Vector3d e1 = (current.row(v) - current.row(j)).transpose();
                s += m->weight[std::size_t(k)] * e0 * e1.transpose();
            }
            if (m->start[std::size_t(v)] == m->start[std::size_t(v) + 1])
                continue;
            const Eigen::Matrix3d r = bestRotation(s);
            rotation[std::size_t(v)] = r;
        }
        // Global step (their equation 9): L x = sum_j w_ij / 2 (R_i + R_j)(p_i - p_j), fixed
        // neighbours moved to the right-hand side, handles as soft springs.
        for (Eigen::Index r = 0; r < rows; ++r) {
            const std::int32_t v = m->freeVertex[std::size_t(r)];
            Eigen::Vector3d b = Eigen::Vector3d::Zero();
            for (std::int32_t k = m->start[std::size_t(v)]; k < m->start[std::size_t(v) + 1]; ++k) {
                const std::int32_t j = m->neighbour[std::size_t(k)];
                const double wij = m->weight[std::size_t(k)];
                const Eigen::Vector3d e0 = (m->rest.row(v) - m->rest.row(j)).transpose();
                b += 0.5 * wij * (rotation[std::size_t(v)] + rotation[std::size_t(j)]) * e0;
                if (m->freeIndex[std::size_t(j)] < 0)
                    b += wij * current.row(j).transpose();
            }
            b += m->handleStiffness[std::size_t(r)] * m->handleTarget.row(r).transpose();
            b += 1e-6 * m->degree[std::size_t(v)] * current.row(v).transpose();
            rhs.row(r) = b.transpose();
        }
        const Eigen::MatrixXd x = m->solver.solve(rhs);
        if (!x.allFinite())
            return true;
        for (Eigen::Index r = 0; r < rows; ++r)
            current.row(m->freeVertex[std::size_t(r)]) = x.row(r);
    }
    return true;
}

} // namespace celform::algo
