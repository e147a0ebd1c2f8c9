// Camera from 2D-3D correspondences for aligning the base model with a drawing (paper 1,
// section 3.1.1 aligns by hand and notes that non-linear methods "might prove useful"): a
// normalised DLT gives a start, Levenberg-Marquardt refines a square-pixel camera in pixels.
#include "celform/algorithms/camera_solve.h"

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <sstream>

namespace celform::algo {

namespace {

constexpr double kPi = 3.14159265358979323846;

void setError(std::string* error, const std::string& message)
{
    if (error)
        *error = message;
}

/// The camera being refined: world-to-camera rotation (rows: right, down, forward in world, the
/// pixel convention x right, y down), eye and focal length in pixels.
struct PinholeState {
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    Eigen::Vector3d eye = Eigen::Vector3d::Zero();
    double focal = 1.0;
};

Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d s;
    s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return s;
}

Eigen::Matrix3d rotationFromAxisAngle(const Eigen::Vector3d& w)
{
    const double angle = w.norm();
    if (angle < 1e-300)
        return Eigen::Matrix3d::Identity();
    return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

/// Similarity that moves points to their centroid and scales them to mean distance sqrt(dim)
/// (Hartley's normalisation). Returns false when all points coincide.
template <int Dim>
bool normalisation(
    const std::vector<Eigen::Matrix<double, Dim, 1>>& points, Eigen::Matrix<double, Dim + 1, Dim + 1>& transform)
{
    Eigen::Matrix<double, Dim, 1> mean = Eigen::Matrix<double, Dim, 1>::Zero();
    for (const auto& p : points)
        mean += p;
    mean /= double(points.size());
    double meanDistance = 0.0;
    for (const auto& p : points)
        meanDistance += (p - mean).norm();
    meanDistance /= double(points.size());
    if (!(meanDistance > 0.0))
        return false;
    const double scale = std::sqrt(double(Dim)) / meanDistance;
    transform.setIdentity();
    transform.template topLeftCorner<Dim, Dim>() *= scale;
    transform.template topRightCorner<Dim, 1>() = -scale * mean;
    return true;
}

/// Residuals (projected minus observed, pixels; 2 per point) and, when jacobian is given, their
/// derivatives by (rotation increment, eye, focal). The rotation increment w acts on the left:
/// rotation' = exp([w]x) rotation. Returns false when a point is not in front of the camera.
bool residuals(const PinholeState& s, const std::vector<Eigen::Vector3d>& points3d,
    const std::vector<Eigen::Vector2d>& points2d, const Eigen::Vector2d& centre, Eigen::VectorXd& r,
    Eigen::MatrixXd* jacobian)
{
    const Eigen::Index n = Eigen::Index(points3d.size());
    r.resize(2 * n);
    if (jacobian)
        jacobian->resize(2 * n, 7);
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Vector3d c = s.rotation * (points3d[std::size_t(i)] - s.eye);
        if (!(c.z() > 1e-12 * (1.0 + c.head<2>().norm())))
            return false;
        const double iz = 1.0 / c.z();
        const Eigen::Vector2d xy = c.head<2>() * iz;
        r.segment<2>(2 * i) = centre + s.focal * xy - points2d[std::size_t(i)];
        if (!jacobian)
            continue;
        // d(pixel)/d(camera point) for u = f x / z, v = f y / z.
        Eigen::Matrix<double, 2, 3> dp;
        dp << s.focal * iz, 0, -s.focal * xy.x() * iz, 0, s.focal * iz, -s.focal * xy.y() * iz;
        // d(camera point)/dw = -[c]x at w = 0; d(camera point)/d(eye) = -rotation.
        jacobian->block<2, 3>(2 * i, 0) = dp * (-skew(c));
        jacobian->block<2, 3>(2 * i, 3) = dp * (-s.rotation);
        jacobian->block<2, 1>(2 * i, 6) = xy;
    }
    return true;
}

/// Hand-written Levenberg-Marquardt with Marquardt's diagonal scaling; steps that put a point
/// behind the camera or make the focal length non-positive are rejected like uphill steps.
void refine(PinholeState& s, const std::vector<Eigen::Vector3d>& points3d, const std::vector<Eigen::Vector2d>& points2d,
    const Eigen::Vector2d& centre)
{
    Eigen::VectorXd r, trialR;
    Eigen::MatrixXd jacobian;
    if (!residuals(s, points3d, points2d, centre, r, &jacobian))
        return;
    double cost = r.squaredNorm();
    double lambda = -1.0;
    for (int iteration = 0; iteration < 200 && cost > 0.0; ++iteration) {
        const Eigen::Matrix<double, 7, 7> h = jacobian.transpose() * jacobian;
        const Eigen::Matrix<double, 7, 1> g = jacobian.transpose() * r;
        Eigen::Matrix<double, 7, 1> diag = h.diagonal().cwiseMax(1e-12 * h.diagonal().maxCoeff());
        if (lambda < 0.0)
            lambda = 1e-3;
        bool improved = false;
        while (lambda < 1e12) {
            Eigen::Matrix<double, 7, 7> a = h;
            a.diagonal() += lambda * diag;
            const Eigen::Matrix<double, 7, 1> step = a.ldlt().solve(-g);
            PinholeState trial = s;
            trial.rotation = rotationFromAxisAngle(step.head<3>()) * s.rotation;
            trial.eye += step.segment<3>(3);
            trial.focal += step(6);
            if (step.allFinite() && trial.focal > 0.0 && residuals(trial, points3d, points2d, centre, trialR, nullptr)
                && trialR.squaredNorm() < cost) {
                const double previous = cost;
                s = trial;
                cost = trialR.squaredNorm();
                lambda = std::max(lambda / 3.0, 1e-12);
                improved = true;
                residuals(s, points3d, points2d, centre, r, &jacobian);
                if (previous - cost <= 1e-14 * previous)
                    return; // converged: no measurable decrease
                break;
            }
            lambda *= 10.0;
        }
        if (!improved)
            return; // no downhill step at any damping: at a minimum
    }
}

/// Normalised DLT (11 unknowns up to scale) for a 3x4 projection matrix in pixels.
bool directLinearTransform(const std::vector<Eigen::Vector3d>& points3d, const std::vector<Eigen::Vector2d>& points2d,
    Eigen::Matrix<double, 3, 4>& projection, std::string* error)
{
    Eigen::Matrix4d t3;
    Eigen::Matrix3d t2;
    if (!normalisation<3>(points3d, t3) || !normalisation<2>(points2d, t2)) {
        setError(error, "The 3D points or the 2D points all coincide.");
        return false;
    }
    const Eigen::Index n = Eigen::Index(points3d.size());
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * n, 12);
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Vector4d x = t3 * points3d[std::size_t(i)].homogeneous();
        const Eigen::Vector3d u = t2 * points2d[std::size_t(i)].homogeneous();
        a.block<1, 4>(2 * i, 0) = x.transpose();
        a.block<1, 4>(2 * i, 8) = -u.x() * x.transpose();
        a.block<1, 4>(2 * i + 1, 4) = x.transpose();
        a.block<1, 4>(2 * i + 1, 8) = -u.y() * x.transpose();
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullV);
    const Eigen::VectorXd sigma = svd.singularValues();
    // A one-dimensional null space is needed: a second (near-)zero singular value means the
    // correspondences do not pin the camera down (e.g. points on a line or a twisted cubic).
    if (sigma.size() < 12 || !(sigma(10) > 1e-9 * sigma(0))) {
        setError(error, "The correspondences are degenerate: the camera is not determined by them.");
        return false;
    }
    const Eigen::VectorXd p = svd.matrixV().col(11);
    Eigen::Matrix<double, 3, 4> normalised;
    normalised << p.segment<4>(0).transpose(), p.segment<4>(4).transpose(), p.segment<4>(8).transpose();
    projection = t2.inverse() * normalised * t3;
    return projection.allFinite();
}

/// P = K [R | t] by RQ decomposition of the left 3x3 block (K upper triangular with a positive
/// diagonal, R a rotation), returning the rotation, the camera centre and K.
bool decompose(
    Eigen::Matrix<double, 3, 4> projection, Eigen::Matrix3d& k, Eigen::Matrix3d& rotation, Eigen::Vector3d& centre)
{
    // P is known up to scale, sign included: choose the sign with det(M) > 0 so that
    // R is a rotation and points in front of the camera have positive depth.
    if (projection.leftCols<3>().determinant() < 0.0)
        projection = -projection;
    const Eigen::Matrix3d m = projection.leftCols<3>();
    if (!(std::abs(m.determinant()) > 0.0))
        return false;
    // RQ through QR of the row-reversed transpose: with J the exchange matrix and
    // (J M)^T = Q U, M = (J U^T J)(J Q^T), an upper-triangular times an orthogonal matrix.
    Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
    j(0, 2) = j(1, 1) = j(2, 0) = 1.0;
    const Eigen::HouseholderQR<Eigen::Matrix3d> qr((j * m).transpose());
    const Eigen::Matrix3d u = qr.matrixQR().triangularView<Eigen::Upper>();
    const Eigen::Matrix3d q = qr.householderQ();
    k = j * u.transpose() * j;
    rotation = j * q.transpose();
    const Eigen::Matrix3d d = k.diagonal().cwiseSign().asDiagonal();
    k = k * d;
    rotation = d * rotation;
    if (rotation.determinant() < 0.0 || !(k(2, 2) > 0.0))
        return false;
    k /= k(2, 2);
    centre = -m.inverse() * projection.col(3);
    return k.allFinite() && rotation.allFinite() && centre.allFinite();
}

} // namespace

std::optional<SolvedCamera> solveCamera(const std::vector<Eigen::Vector3d>& points3d,
    const std::vector<Eigen::Vector2d>& points2d, int imageWidth, int imageHeight, std::string* error)
{
    if (points3d.size() != points2d.size()) {
        std::ostringstream message;
        message << "The number of 3D points (" << points3d.size() << ") and 2D points (" << points2d.size()
                << ") differ.";
        setError(error, message.str());
        return std::nullopt;
    }
    if (points3d.size() < 6) {
        std::ostringstream message;
        message << "At least 6 point pairs are needed to solve for a camera; " << points3d.size() << " given.";
        setError(error, message.str());
        return std::nullopt;
    }
    if (imageWidth <= 0 || imageHeight <= 0) {
        setError(error, "The image size must be positive.");
        return std::nullopt;
    }
    for (std::size_t i = 0; i < points3d.size(); ++i)
        if (!points3d[i].allFinite() || !points2d[i].allFinite()) {
            setError(error, "A point has a non-finite coordinate.");
            return std::nullopt;
        }

    // The DLT cannot separate the camera from a plane's homography: reject (near-)coplanar points
    // by the thinnest extent of their spread relative to the widest.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : points3d)
        mean += p;
    mean /= double(points3d.size());
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const auto& p : points3d)
        scatter += (p - mean) * (p - mean).transpose();
    const Eigen::Vector3d spread = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvalues().cwiseMax(0.0);
    if (!(std::sqrt(spread(0)) > 1e-3 * std::sqrt(spread(2)))) {
        setError(error, "The 3D points are (nearly) coplanar; pick points that are not all on one plane.");
        return std::nullopt;
    }

    Eigen::Matrix<double, 3, 4> projection;
    if (!directLinearTransform(points3d, points2d, projection, error))
        return std::nullopt;
    Eigen::Matrix3d k, rotation;
    Eigen::Vector3d eye;
    if (!decompose(projection, k, rotation, eye)) {
        setError(error, "The linear solution is not a valid camera.");
        return std::nullopt;
    }
    for (const auto& p : points3d)
        if (!(rotation.row(2).dot(p - eye) > 0.0)) {
            setError(error, "Some points are behind the solved camera; check the correspondences.");
            return std::nullopt;
        }

    // Square pixels and the principal point at the image centre from here on.
    PinholeState state;
    state.rotation = rotation;
    state.eye = eye;
    state.focal = 0.5 * (k(0, 0) + k(1, 1));
    if (!(state.focal > 0.0)) {
        setError(error, "The linear solution has a non-positive focal length.");
        return std::nullopt;
    }
    const Eigen::Vector2d centre(0.5 * imageWidth, 0.5 * imageHeight);
    refine(state, points3d, points2d, centre);

    Eigen::VectorXd r;
    if (!residuals(state, points3d, points2d, centre, r, nullptr) || !r.allFinite() || !(state.focal > 0.0)
        || !state.eye.allFinite()) {
        setError(error, "The camera solve did not converge.");
        return std::nullopt;
    }
    SolvedCamera camera;
    camera.eye = state.eye;
    const Eigen::Vector3d forward = state.rotation.row(2).transpose();
    camera.target = state.eye + forward * (mean - state.eye).norm();
    camera.up = -state.rotation.row(1).transpose(); // image y points down
    camera.fovYDegrees = 2.0 * std::atan(0.5 * imageHeight / state.focal) * 180.0 / kPi;
    camera.rmsPixelError = std::sqrt(r.squaredNorm() / double(points3d.size()));
    return camera;
}

Eigen::Vector2d projectToImage(
    const SolvedCamera& camera, const Eigen::Vector3d& point, int imageWidth, int imageHeight)
{
    const Eigen::Vector3d forward = (camera.target - camera.eye).normalized();
    const Eigen::Vector3d right = forward.cross(camera.up).normalized();
    const Eigen::Vector3d up = right.cross(forward);
    const Eigen::Vector3d q = point - camera.eye;
    const double depth = q.dot(forward);
    if (!(depth > 0.0))
        return Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
    const double focal = 0.5 * imageHeight / std::tan(0.5 * camera.fovYDegrees * kPi / 180.0);
    return {0.5 * imageWidth + focal * q.dot(right) / depth, 0.5 * imageHeight - focal * q.dot(up) / depth};
}

} // namespace celform::algo
