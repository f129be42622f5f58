#pragma once
// Meshes the PDE tests fit and cut: a welded UV sphere, a grid over (s, t)
// (closed round t, and round s when asked), an open cylinder and a torus.
#include "mesh/mesh.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace fl::pde::test {

using mesh::Mesh;

constexpr double kPi = std::numbers::pi;

// A welded UV sphere: one vertex at each pole, no seam.
inline Mesh sphere(int rings = 48, int segments = 96, double r = 1) {
    Mesh m;
    m.positions.push_back({0, 0, float(r)});
    for (int i = 1; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const double t = kPi * i / rings, p = 2 * kPi * j / segments;
            m.positions.push_back({float(r * std::sin(t) * std::cos(p)),
                                   float(r * std::sin(t) * std::sin(p)), float(r * std::cos(t))});
        }
    m.positions.push_back({0, 0, float(-r)});
    const auto south = std::uint32_t(m.positions.size() - 1);
    auto at = [&](int i, int j) { return std::uint32_t(1 + (i - 1) * segments + (j % segments)); };
    for (int j = 0; j < segments; ++j)
        m.triangles.push_back({0, at(1, j), at(1, j + 1)});
    for (int i = 1; i + 1 < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    for (int j = 0; j < segments; ++j)
        m.triangles.push_back({at(rings - 1, j), south, at(rings - 1, j + 1)});
    return m;
}

// A grid of rows x columns over (s, t) in [0,1] x [0,1), closed round t
// when `wrap`, its points from `f`.
template <typename F>
Mesh grid(int rows, int columns, bool wrapRows, F&& f) {
    Mesh m;
    const int ringCount = wrapRows ? rows : rows + 1;
    for (int i = 0; i < ringCount; ++i)
        for (int j = 0; j < columns; ++j) {
            const auto p = f(double(i) / rows, double(j) / columns);
            m.positions.push_back({float(p[0]), float(p[1]), float(p[2])});
        }
    auto at = [&](int i, int j) {
        return std::uint32_t((i % ringCount) * columns + (j % columns));
    };
    for (int i = 0; i < rows; ++i)
        for (int j = 0; j < columns; ++j) {
            m.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    return m;
}

inline Mesh cylinder() { // open at both ends
    return grid(24, 96, false, [](double s, double t) {
        return std::array<double, 3>{0.5 * std::cos(2 * kPi * t), 0.5 * std::sin(2 * kPi * t),
                                     2 * s - 1};
    });
}

inline Mesh torus() {
    return grid(64, 32, true, [](double s, double t) {
        const double a = 2 * kPi * s, b = 2 * kPi * t;
        return std::array<double, 3>{(1 + 0.35 * std::cos(b)) * std::cos(a),
                                     (1 + 0.35 * std::cos(b)) * std::sin(a), 0.35 * std::sin(b)};
    });
}

} // namespace fl::pde::test
