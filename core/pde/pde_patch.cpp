#include "pde_patch.h"

#include <cmath>
#include <vector>

namespace fl::pde {

void Patch::setRadii(std::size_t n) {
    cosines.resize(n, Mode{});
    sines.resize(n, Mode{});
}

Basis basis(int n, double a, double u) {
    Basis b{};
    if (n == 0) {
        b.value = {1, u, u * u, u * u * u};
        b.du = {0, 1, 2 * u, 3 * u * u};
        b.du2 = {0, 0, 2, 6 * u};
        return b;
    }
    const double k = a * n;
    const double g = std::exp(-k * (1 - u)), h = std::exp(-k * u);
    // g' = k g, (u g)' = g (1 + k u), (u g)'' = g (2k + k² u); h with -k.
    b.value = {g, u * g, h, u * h};
    b.du = {k * g, g * (1 + k * u), -k * h, h * (1 - k * u)};
    b.du2 = {k * k * g, g * (2 * k + k * k * u), k * k * h, h * (-2 * k + k * k * u)};
    return b;
}

void completeCap(Patch& patch) {
    if (!patch.cap) return;
    for (std::size_t k = 0; k < patch.radii(); ++k) {
        const int n = int(k) + 1;
        const Basis b = basis(n, patch.a, 0.0); // value {g0, 0, 1, 0}, du {k g0, g0, -k, 1}
        for (Mode* m : {&patch.cosines[k], &patch.sines[k]})
            for (std::size_t c = 0; c < 3; ++c) {
                Mode& mode = *m;
                // A(0) = c1 g0 + c3 = 0.
                mode[2][c] = -b.value[0] * mode[0][c];
                // A'(0) = c1 k g0 + c2 g0 - k c3 + c4 = 0.
                if (n >= 2)
                    mode[3][c] =
                        -(mode[0][c] * b.du[0] + mode[1][c] * b.du[1] + mode[2][c] * b.du[2]);
            }
    }
}

void modeBases(std::size_t radii, double a, double u, Basis* out) {
    const double g1 = std::exp(-a * (1 - u)), h1 = std::exp(-a * u);
    double g = 1, h = 1;
    for (std::size_t i = 0; i < radii; ++i) {
        g *= g1;
        h *= h1;
        const double k = a * double(i + 1);
        Basis& b = out[i];
        b.value = {g, u * g, h, u * h};
        b.du = {k * g, g * (1 + k * u), -k * h, h * (1 - k * u)};
        b.du2 = {k * k * g, g * (2 * k + k * k * u), k * k * h, h * (-2 * k + k * k * u)};
    }
}

void harmonics(std::size_t radii, double v, double* cosines, double* sines) {
    const double c1 = std::cos(v), s1 = std::sin(v);
    double c = 1, s = 0;
    for (std::size_t i = 0; i < radii; ++i) {
        const double next = c * c1 - s * s1;
        s = s * c1 + c * s1;
        c = next;
        cosines[i] = c;
        sines[i] = s;
    }
}

namespace {

void addScaled(Vec3& to, const Mode& m, const std::array<double, 4>& w, double s) {
    for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c)
            to[c] += s * w[i] * m[i][c];
}

} // namespace

Point evaluate(const Patch& patch, double u, double v) {
    Point p{};
    const Basis b0 = basis(0, patch.a, u);
    addScaled(p.position, patch.spine, b0.value, 1);
    addScaled(p.du, patch.spine, b0.du, 1);
    const std::size_t radii = patch.radii();
    std::vector<Basis> bases(radii);
    std::vector<double> cosines(radii), sines(radii);
    modeBases(radii, patch.a, u, bases.data());
    harmonics(radii, v, cosines.data(), sines.data());
    for (std::size_t i = 0; i < radii; ++i) {
        const int n = int(i) + 1;
        const Basis& b = bases[i];
        const double c = cosines[i], s = sines[i];
        addScaled(p.position, patch.cosines[i], b.value, c);
        addScaled(p.position, patch.sines[i], b.value, s);
        addScaled(p.du, patch.cosines[i], b.du, c);
        addScaled(p.du, patch.sines[i], b.du, s);
        addScaled(p.dv, patch.cosines[i], b.value, -n * s);
        addScaled(p.dv, patch.sines[i], b.value, n * c);
    }
    return p;
}

Vec3 residual(const Patch& patch, double u, double v, double h, double operatorA) {
    // L X = X_uu + a² X_vv, by central differences; the residual is L(L X).
    const double a = operatorA > 0 ? operatorA : patch.a;
    const double a2 = a * a;
    auto L = [&](double uu, double vv) {
        Vec3 out{};
        const Vec3 c = position(patch, uu, vv);
        const Vec3 up = position(patch, uu + h, vv), um = position(patch, uu - h, vv);
        const Vec3 vp = position(patch, uu, vv + h), vm = position(patch, uu, vv - h);
        for (int k = 0; k < 3; ++k)
            out[k] =
                (up[k] - 2 * c[k] + um[k]) / (h * h) + a2 * (vp[k] - 2 * c[k] + vm[k]) / (h * h);
        return out;
    };
    Vec3 out{};
    const Vec3 c = L(u, v), up = L(u + h, v), um = L(u - h, v), vp = L(u, v + h), vm = L(u, v - h);
    for (int k = 0; k < 3; ++k)
        out[k] = (up[k] - 2 * c[k] + um[k]) / (h * h) + a2 * (vp[k] - 2 * c[k] + vm[k]) / (h * h);
    return out;
}

} // namespace fl::pde
