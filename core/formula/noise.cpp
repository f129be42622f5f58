#include "noise.h"

#include <cmath>
#include <cstdint>

namespace fl::formula {
namespace {

// Ken Perlin's reference permutation (2002), repeated to avoid wrapping.
constexpr std::uint8_t kPerm[256] = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103,
    30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,
    197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174,
    20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231,
    83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143,
    54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196,
    135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124,
    123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,
    182, 189, 28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101,
    155, 167, 43,  172, 9,   129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185,
    112, 104, 218, 246, 97,  228, 251, 34,  242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,
    51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176,
    115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243,
    141, 128, 195, 78,  66,  215, 61,  156, 180};

inline int perm(int i) {
    return kPerm[i & 255];
}

// The 12 edge gradients of a cube (plus 4 repeats), as Perlin's grad().
inline void gradVec(int hash, double g[3]) {
    static constexpr double kG[16][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                         {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                         {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1},
                                         {1, 1, 0}, {0, -1, 1}, {-1, 1, 0}, {0, -1, -1}};
    const double* v = kG[hash & 15];
    g[0] = v[0];
    g[1] = v[1];
    g[2] = v[2];
}

inline double fade(double t) {
    return t * t * t * (t * (t * 6 - 15) + 10);
}
inline double fadeDerivative(double t) {
    return 30 * t * t * (t * (t - 2) + 1);
}

// Reduce a coordinate to its lattice cell and the offset in [0, 1). Huge or
// non-finite coordinates are reduced modulo 256 first so the cell index never
// overflows an int (the noise repeats every 256 units anyway).
inline void split(double v, int& cell, double& frac) {
    if (!std::isfinite(v)) {
        cell = 0;
        frac = 0.0;
        return;
    }
    double fl = std::floor(v);
    frac = v - fl;
    if (frac >= 1.0) frac = std::nextafter(1.0, 0.0);
    cell = static_cast<int>(std::fmod(fl, 256.0));
    if (cell < 0) cell += 256;
}

} // namespace

double noise3Gradient(double x, double y, double z, double grad[3]) {
    if (std::isnan(x) || std::isnan(y) || std::isnan(z)) {
        grad[0] = grad[1] = grad[2] = 0.0;
        return NAN;
    }
    int X, Y, Z;
    double fx, fy, fz;
    split(x, X, fx);
    split(y, Y, fy);
    split(z, Z, fz);
    double u = fade(fx), v = fade(fy), w = fade(fz);
    double du = fadeDerivative(fx), dv = fadeDerivative(fy), dw = fadeDerivative(fz);

    double value = 0.0;
    double gx = 0.0, gy = 0.0, gz = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        int cx = corner & 1, cy = (corner >> 1) & 1, cz = (corner >> 2) & 1;
        int h = perm(perm(perm(X + cx) + Y + cy) + Z + cz);
        double g[3];
        gradVec(h, g);
        double dx = fx - cx, dy = fy - cy, dz = fz - cz;
        double dot = g[0] * dx + g[1] * dy + g[2] * dz;
        double wx = cx ? u : 1 - u, wy = cy ? v : 1 - v, wz = cz ? w : 1 - w;
        double dwx = cx ? du : -du, dwy = cy ? dv : -dv, dwz = cz ? dw : -dw;
        value += wx * wy * wz * dot;
        gx += dwx * wy * wz * dot + wx * wy * wz * g[0];
        gy += wx * dwy * wz * dot + wx * wy * wz * g[1];
        gz += wx * wy * dwz * dot + wx * wy * wz * g[2];
    }
    grad[0] = gx;
    grad[1] = gy;
    grad[2] = gz;
    return value;
}

double noise3(double x, double y, double z) {
    double g[3];
    return noise3Gradient(x, y, z, g);
}

} // namespace fl::formula
