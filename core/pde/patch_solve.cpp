#include "patch_solve.h"

#include <Eigen/Dense>

#include <cmath>
#include <numbers>

namespace fl::pde {
namespace {

bool finite(const Vec3& p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

bool fail(std::string* why, const std::string& text) {
    if (why) *why = text;
    return false;
}

// Column layout of one patch's unknowns: the spine's 4, then for each n the
// 4 cosine and the 4 sine coefficients.
std::size_t columns(std::size_t radii) {
    return 4 + 8 * radii;
}

// Scratch for the modes' bases and harmonics of one row.
struct RowScratch {
    std::vector<Basis> bases;
    std::vector<double> cosines, sines;
    explicit RowScratch(std::size_t radii) : bases(radii), cosines(radii), sines(radii) {}
};

void designRow(double u, double v, const FitOptions& o, RowScratch& scratch, double* row) {
    const Basis b0 = basis(0, o.a, u);
    for (int i = 0; i < 4; ++i)
        row[i] = b0.value[std::size_t(i)];
    modeBases(o.radii, o.a, u, scratch.bases.data());
    harmonics(o.radii, v, scratch.cosines.data(), scratch.sines.data());
    for (std::size_t k = 0; k < o.radii; ++k) {
        const Basis& b = scratch.bases[k];
        const double c = scratch.cosines[k], s = scratch.sines[k];
        for (int i = 0; i < 4; ++i) {
            row[4 + 8 * k + std::size_t(i)] = b.value[std::size_t(i)] * c;
            row[4 + 8 * k + 4 + std::size_t(i)] = b.value[std::size_t(i)] * s;
        }
    }
}

Patch patchFrom(const Eigen::MatrixXd& x, std::size_t radii, double a) {
    Patch p;
    p.a = a;
    p.setRadii(radii);
    auto mode = [&](std::size_t first, Mode& m) {
        for (std::size_t i = 0; i < 4; ++i)
            for (int c = 0; c < 3; ++c)
                m[i][std::size_t(c)] = x(Eigen::Index(first + i), c);
    };
    mode(0, p.spine);
    for (std::size_t k = 0; k < radii; ++k) {
        mode(4 + 8 * k, p.cosines[k]);
        mode(4 + 8 * k + 4, p.sines[k]);
    }
    return p;
}

} // namespace

std::optional<Patch> fromBoundaryCurves(const BoundaryCurves& c, std::size_t radii, double a,
                                        std::string* why) {
    const std::size_t m = c.curves[0].size();
    for (const auto& curve : c.curves) {
        if (curve.size() != m)
            return fail(why, "the four curves have different point counts"), std::nullopt;
        for (const Vec3& p : curve)
            if (!finite(p)) return fail(why, "a curve point is not a finite number"), std::nullopt;
    }
    if (m < 2 * radii + 1)
        return fail(why, std::to_string(radii) + " radii need at least " +
                             std::to_string(2 * radii + 1) + " points per curve, not " +
                             std::to_string(m)),
               std::nullopt;
    if (!(0 < c.u1 && c.u1 < c.u2 && c.u2 < 1))
        return fail(why, "the inner curves must lie at 0 < u1 < u2 < 1"), std::nullopt;
    if (!(a > 0) || !std::isfinite(a)) return fail(why, "a must be positive"), std::nullopt;
    const std::array<double, 4> at{0.0, c.u1, c.u2, 1.0};
    // Fourier coefficients of every curve: mean, and 2/M Σ C cos(nv), 2/M Σ C sin(nv).
    Patch p;
    p.a = a;
    p.setRadii(radii);
    for (std::size_t n = 0; n <= radii; ++n) {
        Eigen::Matrix4d basisAt;
        for (int k = 0; k < 4; ++k) {
            const Basis b = basis(int(n), a, at[std::size_t(k)]);
            for (int i = 0; i < 4; ++i)
                basisAt(k, i) = b.value[std::size_t(i)];
        }
        const Eigen::PartialPivLU<Eigen::Matrix4d> lu(basisAt);
        for (int part = 0; part < (n == 0 ? 1 : 2); ++part) {
            Eigen::Matrix<double, 4, 3> rhs = Eigen::Matrix<double, 4, 3>::Zero();
            for (int k = 0; k < 4; ++k)
                for (std::size_t j = 0; j < m; ++j) {
                    const double v = 2 * std::numbers::pi * double(j) / double(m);
                    const double w = n == 0      ? 1.0 / double(m)
                                     : part == 0 ? 2.0 / double(m) * std::cos(double(n) * v)
                                                 : 2.0 / double(m) * std::sin(double(n) * v);
                    for (int xyz = 0; xyz < 3; ++xyz)
                        rhs(k, xyz) += w * c.curves[std::size_t(k)][j][std::size_t(xyz)];
                }
            const Eigen::Matrix<double, 4, 3> x = lu.solve(rhs);
            Mode& mode = n == 0 ? p.spine : part == 0 ? p.cosines[n - 1] : p.sines[n - 1];
            for (int i = 0; i < 4; ++i)
                for (int xyz = 0; xyz < 3; ++xyz)
                    mode[std::size_t(i)][std::size_t(xyz)] = x(i, xyz);
        }
    }
    return p;
}

std::optional<Patch> fitToPoints(const std::vector<Sample>& samples, const FitOptions& o,
                                 std::string* why) {
    const std::size_t cols = columns(o.radii);
    if (samples.size() < cols)
        return fail(why, std::to_string(samples.size()) + " points cannot fix " +
                             std::to_string(cols) + " coefficients (" + std::to_string(o.radii) +
                             " radii)"),
               std::nullopt;
    if (!(o.a > 0) || !std::isfinite(o.a)) return fail(why, "a must be positive"), std::nullopt;
    double total = 0;
    for (const Sample& s : samples) {
        if (!finite(s.point) || !std::isfinite(s.u) || !std::isfinite(s.v) || !(s.weight >= 0) ||
            !std::isfinite(s.weight))
            return fail(why, "a point, parameter or weight is not a finite number"), std::nullopt;
        total += s.weight;
    }
    if (!(total > 0)) return fail(why, "every weight is zero"), std::nullopt;
    // Normal equations, accumulated a block of rows at a time (a rank-k
    // update and a product per block, not one per row; never the whole
    // rows x columns matrix): the columns are at most a few hundred.
    const Eigen::Index n = Eigen::Index(cols);
    Eigen::MatrixXd ata = Eigen::MatrixXd::Zero(n, n);
    Eigen::MatrixXd atb = Eigen::MatrixXd::Zero(n, 3);
    constexpr Eigen::Index kBlock = 256;
    Eigen::MatrixXd rows(kBlock, n), targets(kBlock, 3);
    RowScratch scratch(o.radii);
    Eigen::VectorXd row(n);
    Eigen::Index filled = 0;
    auto flush = [&] {
        if (filled == 0) return;
        const auto r = rows.topRows(filled);
        ata.selfadjointView<Eigen::Lower>().rankUpdate(r.transpose());
        atb.noalias() += r.transpose() * targets.topRows(filled);
        filled = 0;
    };
    for (const Sample& s : samples) {
        const double w = std::sqrt(s.weight);
        designRow(s.u, s.v, o, scratch, row.data());
        rows.row(filled) = w * row.transpose();
        for (int c = 0; c < 3; ++c)
            targets(filled, c) = w * s.point[std::size_t(c)];
        if (++filled == kBlock) flush();
    }
    flush();
    ata = ata.selfadjointView<Eigen::Lower>();
    if (o.pointAtStart) {
        // An(0) = Bn(0) = 0 for n >= 1: the u = 0 curve is the spine's start.
        // With `smoothPole` also An'(0) = Bn'(0) = 0 for n >= 2: near the pole
        // only the first radius grows linearly, so the surface has one tangent
        // plane there (no creases fanning out from the pole). Heavy rows on
        // exactly those combinations (not on the spine).
        const double heavy = 1e6 * total;
        auto pin = [&](std::size_t k, const std::array<double, 4>& row) {
            for (int part = 0; part < 2; ++part) {
                Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
                for (std::size_t i = 0; i < 4; ++i)
                    r(Eigen::Index(4 + 8 * k + 4 * std::size_t(part) + i)) = row[i];
                ata += heavy * r * r.transpose();
            }
        };
        for (std::size_t k = 0; k < o.radii; ++k) {
            const Basis b = basis(int(k) + 1, o.a, 0.0);
            pin(k, b.value);
            if (o.smoothPole && k >= 1) pin(k, b.du);
        }
    }
    ata.diagonal().array() += o.ridge * total;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(ata);
    if (ldlt.info() != Eigen::Success)
        return fail(why, "the fit's equations are singular"), std::nullopt;
    const Eigen::MatrixXd x = ldlt.solve(atb);
    if (!x.allFinite()) return fail(why, "the fit did not give finite coefficients"), std::nullopt;
    Patch p = patchFrom(x, o.radii, o.a);
    // The heavy rows hold the cap's conditions to about 1e-6; exactly now.
    p.cap = o.pointAtStart && o.smoothPole;
    completeCap(p);
    return p;
}

} // namespace fl::pde
