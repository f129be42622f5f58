#include "qef.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace fl::mesh {

namespace {
// (A symmetric matrix reads the same by rows or by columns.)
Eigen::Matrix3d matrixOf(const std::array<double, 9>& m) {
    return Eigen::Map<const Eigen::Matrix3d>(m.data());
}
Eigen::Vector3d vectorOf(const std::array<double, 3>& v) {
    return {v[0], v[1], v[2]};
}
// Relative to a QEF's origin, E(y) = y^T M y - 2 y^T r + const (M = A^T A):
// the free coordinates of y minimise E with the held ones fixed, about the
// mass point c, eigenvalues under `cutoff` times a scale truncated — the
// free block's largest eigenvalue, or M's largest diagonal entry.
void minimiseFree(const std::array<bool, 3>& held, Eigen::Vector3d& y, const Eigen::Matrix3d& m,
                  const Eigen::Vector3d& r, const Eigen::Vector3d& c, double cutoff,
                  bool relativeToFree) {
    // M_ff y_f = r_f - M_fh y_h.
    int free[3], nf = 0;
    for (int a = 0; a < 3; ++a)
        if (!held[std::size_t(a)]) free[nf++] = a;
    if (nf == 0) return;
    // At most 3 x 3: fixed-capacity storage, no allocation per cell.
    using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
    using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
    Small mff(nf, nf);
    SmallVector rhs(nf);
    for (int i = 0; i < nf; ++i) {
        double v = r[free[i]];
        for (int a = 0; a < 3; ++a)
            v -= m(free[i], a) * (held[std::size_t(a)] ? y[a] : c[a]);
        rhs[i] = v;
        for (int j = 0; j < nf; ++j)
            mff(i, j) = m(free[i], free[j]);
    }
    Eigen::SelfAdjointEigenSolver<Small> eig(mff);
    // (Relative to the free block, but never under solveInBox's floor: a
    // surface nearly tangent to a held face leaves the block only noise,
    // which its own scale would keep and invert.)
    const double whole = std::max({m(0, 0), m(1, 1), m(2, 2)});
    const double scale =
        relativeToFree ? std::max(eig.eigenvalues().cwiseAbs().maxCoeff(), 0.01 * whole) : whole;
    SmallVector delta = SmallVector::Zero(nf);
    for (int k = 0; k < nf; ++k) {
        const double value = eig.eigenvalues()[k];
        if (!(std::abs(value) >= cutoff * scale) || value == 0) continue;
        const SmallVector v = eig.eigenvectors().col(k);
        delta += v * (v.dot(rhs) / value);
    }
    for (int i = 0; i < nf; ++i)
        y[free[i]] = c[free[i]] + delta[i];
}
} // namespace

std::array<double, 3> Qef::massPoint() const {
    if (!count()) return {0, 0, 0};
    const std::array<double, 3> c = meanOffset();
    return {origin_[0] + c[0], origin_[1] + c[1], origin_[2] + c[2]};
}

std::array<double, 3> Qef::solve(double relativeCutoff) const {
    if (!count()) return {0, 0, 0};
    const Eigen::Matrix3d ata = matrixOf(normalMatrix());
    // About the mass point c (relative to the origin): minimise |A (c + x) - b|,
    // i.e. A^T A x = A^T b - A^T A c.
    const Eigen::Vector3d c = vectorOf(meanOffset());
    const Eigen::Vector3d rhs = Eigen::Vector3d(sumAtb(0), sumAtb(1), sumAtb(2)) - ata * c;
    // The answer is the mass point moved by x.
    auto movedBy = [&](const Eigen::Vector3d& x) -> std::array<double, 3> {
        return {origin_[0] + c[0] + x[0], origin_[1] + c[1] + x[1], origin_[2] + c[2] + x[2]};
    };
    // Nearly parallel unit normals (a smooth patch, most cells): A is about
    // rank one along their mean, the other eigenvalues fall under any sensible
    // cutoff, and the truncated solution moves along the mean normal only —
    // no eigen-decomposition needed.
    const Eigen::Vector3d nsum(sumNormals(0), sumNormals(1), sumNormals(2));
    const double nsumLength = nsum.norm();
    const double spread = nsumLength / count(); // 1 when all normals agree
    if (relativeCutoff >= 0.05 && spread > 0.9995) {
        const Eigen::Vector3d n = nsum / nsumLength;
        const double along = n.dot(ata * n);
        return movedBy(along > 0 ? Eigen::Vector3d(n * (n.dot(rhs) / along))
                                 : Eigen::Vector3d::Zero());
    }
    // One direction dominant (a curved patch: most cells at low
    // resolutions). The Rayleigh quotient r of the mean normal n is at most
    // the largest eigenvalue, and the other two (never negative) sum to
    // trace - (largest) <= trace - r: when that is under cutoff * r, only the
    // dominant eigenvector is kept, and power iteration from n finds it, each
    // step shrinking the error by lambda2 / lambda1 <= q = (trace - r) / r —
    // a few multiplications where the closed form takes an atan2, a sine and
    // a cosine.
    const double trace = ata(0, 0) + ata(1, 1) + ata(2, 2);
    if (nsumLength > 0) {
        Eigen::Vector3d v = nsum / nsumLength;
        const double r0 = v.dot(ata * v);
        const double q = (trace - r0) / r0;
        // (Cutoffs of the mesher's size only: near 1 the iteration would
        // converge too slowly to trust 40 steps.)
        if (r0 > 0 && q < relativeCutoff && relativeCutoff <= 0.25) {
            // q^steps below 1e-10 (the start's error is under 1; counted
            // by multiplying: a logarithm cost as much as the steps): the
            // vertex moves by at most a cell, and is kept in single
            // precision (6e-8 of its coordinates), so an eigenvector off by
            // 1e-10 never shows (1e-16 took twice the steps for the same
            // meshes, but for coordinates within 1e-33 of 0); rescaled every
            // few steps (lambda1 is at most the count of planes, so nothing
            // overflows in between).
            int steps = 1;
            for (double error = q; error > 1e-10 && steps < 40; error *= q)
                ++steps;
            for (int step = 0; step < steps; ++step) {
                v = ata * v;
                if (step % 4 == 3 || step + 1 == steps) v /= v.norm();
            }
            const double r = v.dot(ata * v);
            if (r > 0 && std::isfinite(r)) return movedBy(v * (v.dot(rhs) / r));
        }
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(ata); // closed form for 3x3: several times faster than the iterative solver
    const Eigen::Vector3d values = eig.eigenvalues();
    const double largest = values.cwiseAbs().maxCoeff();
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    if (largest > 0)
        for (int k = 0; k < 3; ++k) {
            if (std::abs(values[k]) < relativeCutoff * largest) continue;
            const Eigen::Vector3d v = eig.eigenvectors().col(k);
            x += v * (v.dot(rhs) / values[k]);
        }
    return movedBy(x);
}

std::array<double, 3> Qef::solveInBox(const std::array<double, 3>& lo,
                                      const std::array<double, 3>& hi,
                                      double relativeCutoff) const {
    std::array<double, 3> x = solve(relativeCutoff);
    if (!count()) return x;
    auto outside = [&](const std::array<double, 3>& p, std::size_t a) {
        return !(p[a] >= lo[a] && p[a] <= hi[a]); // NaN counts as outside
    };
    if (!outside(x, 0) && !outside(x, 1) && !outside(x, 2)) return x;
    const Eigen::Vector3d c = vectorOf(meanOffset());
    Eigen::Vector3d y(c);
    for (std::size_t a = 0; a < 3; ++a)
        y[Eigen::Index(a)] =
            (std::isfinite(x[a]) ? x[a] : origin_[a] + c[Eigen::Index(a)]) - origin_[a];
    return heldInBox({}, {y[0], y[1], y[2]}, lo, hi, relativeCutoff);
}

std::array<double, 3> Qef::solveOnPlanes(const std::array<bool, 3>& held,
                                         const std::array<double, 3>& at,
                                         const std::array<double, 3>& lo,
                                         const std::array<double, 3>& hi,
                                         double relativeCutoff) const {
    if (!count()) return solve(relativeCutoff);
    const Eigen::Matrix3d m = matrixOf(normalMatrix());
    const Eigen::Vector3d r(sumAtb(0), sumAtb(1), sumAtb(2));
    const Eigen::Vector3d c = vectorOf(meanOffset());
    Eigen::Vector3d y(c);
    for (std::size_t a = 0; a < 3; ++a)
        if (held[a]) y[Eigen::Index(a)] = at[a] - origin_[a];
    // The free coordinates on the plane (or line): their own eigenvalues
    // decide what is kept, the held axes' planes (which the caller's face
    // crossings are, all of their weight on a held axis) set no scale.
    minimiseFree(held, y, m, r, c, relativeCutoff, true);
    for (std::size_t a = 0; a < 3; ++a) // sums that overflowed: the mass point
        if (!std::isfinite(y[Eigen::Index(a)]))
            y[Eigen::Index(a)] = held[a] ? at[a] - origin_[a] : c[Eigen::Index(a)];
    return heldInBox(held, {y[0], y[1], y[2]}, lo, hi, relativeCutoff);
}

std::array<double, 3> Qef::heldInBox(std::array<bool, 3> held, const std::array<double, 3>& from,
                                     const std::array<double, 3>& lo,
                                     const std::array<double, 3>& hi, double relativeCutoff) const {
    Eigen::Vector3d y = vectorOf(from);
    // Relative to the origin: E(y) = y^T M y - 2 y^T r + const, M = A^T A.
    const Eigen::Matrix3d m = matrixOf(normalMatrix());
    const Eigen::Vector3d r(sumAtb(0), sumAtb(1), sumAtb(2));
    const Eigen::Vector3d c = vectorOf(meanOffset());
    for (int round = 0; round < 3; ++round) {
        // Hold every coordinate outside the box on the face it crossed.
        bool any = false;
        for (std::size_t a = 0; a < 3; ++a) {
            const double p = origin_[a] + y[Eigen::Index(a)];
            if (held[a] || (p >= lo[a] && p <= hi[a])) continue;
            held[a] = true;
            any = true;
            y[Eigen::Index(a)] = (p < lo[a] ? lo[a] : hi[a]) - origin_[a];
        }
        if (!any) break;
        // The others minimise again, with a cutoff a hundred times lower
        // than solve()'s: the box bounds the answer now, and a crease that
        // runs obliquely to the held face needs the small eigenvalue (a
        // cutoff of solve()'s size kept the vertex off the crease by a
        // third of a cell on the watermelon's cut).
        minimiseFree(held, y, m, r, c, 0.01 * relativeCutoff, false);
    }
    // In the box, and finite whatever the sums did (planes at 1e300 overflow
    // them): the mass point, or the box's centre, stands in for a NaN.
    const std::array<double, 3> mass = massPoint();
    std::array<double, 3> out{};
    for (std::size_t a = 0; a < 3; ++a) {
        double v = origin_[a] + y[Eigen::Index(a)];
        if (!std::isfinite(v)) v = mass[a];
        if (!std::isfinite(v)) v = lo[a] / 2 + hi[a] / 2;
        out[a] = std::clamp(v, lo[a], hi[a]);
    }
    return out;
}

} // namespace fl::mesh
