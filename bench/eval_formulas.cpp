#include "eval_formulas.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace fl::bench {

namespace {

constexpr int kSpheres = 50;

struct SphereSet {
    double cx[kSpheres], cy[kSpheres], cz[kSpheres], r2[kSpheres];
    SphereSet() {
        // a fixed, reproducible scatter (no RNG: the three forms must agree)
        for (int i = 0; i < kSpheres; ++i) {
            cx[i] = std::sin(1.7 * i) * 0.9;
            cy[i] = std::cos(2.3 * i) * 0.9;
            cz[i] = std::sin(0.9 * i + 1.0) * 0.9;
            double r = 0.1 + 0.05 * (i % 4);
            r2[i] = r * r;
        }
    }
};
const SphereSet& spheres() {
    static const SphereSet s;
    return s;
}

void nativeSphere(const double* x, const double* y, const double* z, double, double* out,
                  std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        out[i] = 1.0 - x[i] * x[i] - y[i] * y[i] - z[i] * z[i];
}

void nativeWatermelon(const double* x, const double* y, const double* z, double, double* out,
                      std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
        double ball = 1.0 - x[i] * x[i] - y[i] * y[i] - z[i] * z[i];
        double wedge = std::min(std::min(z[i] - x[i], y[i]), z[i]);
        out[i] = std::min(ball, -wedge);
    }
}

void nativeWatermelonColour(const double* x, const double* y, const double* z, double, double* out,
                            std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        out[i] =
            0.01 * (std::sin(12.0 * std::atan2(x[i], z[i] + 0.04 * std::sin(25.0 * y[i]))) - 0.7);
}

void nativeGyroid(const double* x, const double* y, const double* z, double, double* out,
                  std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
        double sx = std::sin(4.0 * x[i]), cx = std::cos(4.0 * x[i]);
        double sy = std::sin(4.0 * y[i]), cy = std::cos(4.0 * y[i]);
        double sz = std::sin(4.0 * z[i]), cz = std::cos(4.0 * z[i]);
        out[i] = sx * cy + sy * cz + sz * cx;
    }
}

void nativeBouncing(const double* x, const double* y, const double* z, double t, double* out,
                    std::size_t n) {
    const double h = std::abs(std::sin(std::numbers::pi * t)) - 0.5;
    for (std::size_t i = 0; i < n; ++i) {
        double dy = y[i] - h;
        out[i] = 0.25 - x[i] * x[i] - dy * dy - z[i] * z[i];
    }
}

void nativeUnion50(const double* x, const double* y, const double* z, double, double* out,
                   std::size_t n) {
    const SphereSet& s = spheres();
    for (std::size_t i = 0; i < n; ++i) {
        double best = -1e300;
        for (int k = 0; k < kSpheres; ++k) {
            double dx = x[i] - s.cx[k], dy = y[i] - s.cy[k], dz = z[i] - s.cz[k];
            best = std::max(best, s.r2[k] - (dx * dx + dy * dy + dz * dz));
        }
        out[i] = best;
    }
}

std::string number(double v) {
    std::ostringstream os;
    os.precision(17);
    os << v;
    return os.str();
}

std::string union50(bool muparser) {
    const SphereSet& s = spheres();
    std::string src;
    for (int k = 0; k < kSpheres; ++k) {
        std::string term = number(s.r2[k]) + " - ((x - " + number(s.cx[k]) + ")^2 + (y - " +
                           number(s.cy[k]) + ")^2 + (z - " + number(s.cz[k]) + ")^2)";
        if (k == 0)
            src = term;
        else if (muparser)
            src = "max(" + src + ", " + term + ")";
        else
            src += " | " + term;
    }
    return src;
}

} // namespace

const std::vector<EvalFormula>& evalFormulas() {
    static const std::vector<EvalFormula> formulas = {
        {"sphere", "1 - x^2 - y^2 - z^2", "1 - x^2 - y^2 - z^2", nativeSphere},
        {"watermelon", "(1-x^2-y^2-z^2) & (-((z-x) & y & z))",
         "min(1-x^2-y^2-z^2, -min(min(z-x, y), z))", nativeWatermelon},
        {"watermelon_colour", "0.01*(sin(12*atan(x, z + 0.04*sin(25*y))) - 0.7)",
         "0.01*(sin(12*atan2(x, z + 0.04*sin(25*y))) - 0.7)", nativeWatermelonColour},
        {"gyroid", "sin(4*x)*cos(4*y) + sin(4*y)*cos(4*z) + sin(4*z)*cos(4*x)",
         "sin(4*x)*cos(4*y) + sin(4*y)*cos(4*z) + sin(4*z)*cos(4*x)", nativeGyroid},
        {"bouncing_sphere", "0.25 - x^2 - (y - (abs(sin(pi*t)) - 0.5))^2 - z^2",
         "0.25 - x^2 - (y - (abs(sin(_pi*t)) - 0.5))^2 - z^2", nativeBouncing},
        {"union50", union50(false), union50(true), nativeUnion50},
    };
    return formulas;
}

Grid makeGrid(std::size_t side) {
    Grid g;
    const std::size_t n = side * side * side;
    g.x.resize(n);
    g.y.resize(n);
    g.z.resize(n);
    const double step = side > 1 ? 2.4 / static_cast<double>(side - 1) : 0.0;
    std::size_t i = 0;
    for (std::size_t k = 0; k < side; ++k)
        for (std::size_t j = 0; j < side; ++j)
            for (std::size_t l = 0; l < side; ++l, ++i) {
                g.x[i] = -1.2 + step * static_cast<double>(l);
                g.y[i] = -1.2 + step * static_cast<double>(j);
                g.z[i] = -1.2 + step * static_cast<double>(k);
            }
    return g;
}

} // namespace fl::bench
