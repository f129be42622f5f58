#include "qef.h"

#include <Eigen/Eigenvalues>

namespace fl::mesh {

void Qef::add(const std::array<double, 3>& p, const std::array<double, 3>& n) {
    if (count_ < 12) {
        points_[std::size_t(count_)] = p;
        normals_[std::size_t(count_)] = n;
    }
    ++count_;
    for (int a = 0; a < 3; ++a)
        pointSum_[std::size_t(a)] += p[std::size_t(a)];
}

std::array<double, 3> Qef::massPoint() const {
    if (!count_) return {0, 0, 0};
    return {pointSum_[0] / count_, pointSum_[1] / count_, pointSum_[2] / count_};
}

std::array<double, 3> Qef::solve(double relativeCutoff) const {
    const std::array<double, 3> c = massPoint();
    // Built about the mass point: A^T A x = A^T b with b_i = n_i . (p_i - c).
    Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
    Eigen::Vector3d atb = Eigen::Vector3d::Zero();
    const int n = count_ < 12 ? count_ : 12;
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d normal(normals_[std::size_t(i)][0], normals_[std::size_t(i)][1],
                                     normals_[std::size_t(i)][2]);
        const Eigen::Vector3d offset(points_[std::size_t(i)][0] - c[0],
                                     points_[std::size_t(i)][1] - c[1],
                                     points_[std::size_t(i)][2] - c[2]);
        ata += normal * normal.transpose();
        atb += normal * normal.dot(offset);
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(ata); // closed form for 3x3: several times faster than the iterative solver
    const Eigen::Vector3d values = eig.eigenvalues();
    const double largest = values.cwiseAbs().maxCoeff();
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    if (largest > 0) {
        for (int k = 0; k < 3; ++k) {
            if (std::abs(values[k]) < relativeCutoff * largest) continue;
            const Eigen::Vector3d v = eig.eigenvectors().col(k);
            x += v * (v.dot(atb) / values[k]);
        }
    }
    return {c[0] + x[0], c[1] + x[1], c[2] + x[2]};
}

} // namespace fl::mesh
