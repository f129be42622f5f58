#pragma once
// One Bloor–Wilson PDE patch (the paper's Section 4): the solution of
//     (d²/du² + a² d²/dv²)² X = 0,   0 <= u <= 1, 0 <= v < 2π,
// by separation of variables, kept to N "radii":
//     X(u, v) = A0(u) + Σ_{n=1..N} An(u) cos(nv) + Bn(u) sin(nv)
//     A0(u)   = α0 + α1 u + α2 u² + α3 u³                 (the spine)
//     An(u)   = αn1 g(u) + αn2 u g(u) + αn3 h(u) + αn4 u h(u)   (and Bn with βn)
// with g(u) = e^{-an(1-u)} and h(u) = e^{-anu}. The paper writes e^{anu};
// g is that scaled by e^{-an}, so every basis function stays within [0, 1]
// on the patch and the coefficients stay of the shape's size however large
// a·n grows (the same surfaces, a better conditioned sum). Mc = 4(2N+1)
// vector coefficients.
#include <array>
#include <cstddef>
#include <vector>

namespace fl::pde {

using Vec3 = std::array<double, 3>;
using Mode = std::array<Vec3, 4>; // the four vector coefficients of one An or Bn (or A0)

struct Patch {
    double a = 1; // smoothing between u and v (the paper's a >= 1)
    // A cap: C0 is one point with one tangent plane there — An(0) = Bn(0) = 0
    // for n >= 1 and An'(0) = Bn'(0) = 0 for n >= 2. Then c3 (and for n >= 2
    // c4) of every mode follow from c1 and c2 (completeCap); files keep only those.
    bool cap = false;
    Mode spine{};              // α0..α3: the cubic A0(u)
    std::vector<Mode> cosines; // An, n = 1..N
    std::vector<Mode> sines;   // Bn, n = 1..N

    std::size_t radii() const { return cosines.size(); }
    void setRadii(std::size_t n); // keeps what fits, zero beyond
    std::size_t coefficientCount() const { return 4 * (2 * radii() + 1); } // Mc
};

// Sets the coefficients a cap's conditions fix from the free ones.
void completeCap(Patch& patch);
// Whether coefficient i (0..3) of mode n (>= 1) of a cap follows from the others.
inline bool capDerived(int n, int i) {
    return i == 2 || (n >= 2 && i == 3);
}

// The four basis functions of mode n at u (n = 0: 1, u, u², u³), and their
// first and second derivatives in u.
struct Basis {
    std::array<double, 4> value, du, du2;
};
Basis basis(int n, double a, double u);
// basis(n, a, u) for n = 1..radii into out[0..radii-1], with two exponentials
// in all (g and h of mode n are those of mode 1 to the n-th power).
void modeBases(std::size_t radii, double a, double u, Basis* out);
// cos(nv) and sin(nv) for n = 1..radii, with one sine and cosine in all
// (angle addition, accurate to a few ulps for the radii a patch has).
void harmonics(std::size_t radii, double v, double* cosines, double* sines);

struct Point {
    Vec3 position, du, dv; // X and its partial derivatives
};
Point evaluate(const Patch& patch, double u, double v);
inline Vec3 position(const Patch& patch, double u, double v) {
    return evaluate(patch, u, v).position;
}

// Applies the PDE's operator (with `operatorA`, the patch's own a when 0)
// to X at (u, v) by central differences of step h (tests: a patch satisfies
// its equation, and not another a's).
Vec3 residual(const Patch& patch, double u, double v, double h, double operatorA = 0);

} // namespace fl::pde
