#include "shape_samples.h"

namespace fl::grading {

std::vector<mesh::Vec3f> pointsInside(const field::ImplicitField& f, Budget& budget,
                                      std::size_t most) {
    constexpr int n = 24; // a grid of n^3 points of the box, at the cells' centres
    field::ImplicitField open = f;
    open.boundary = field::BoxBoundary::Open;
    field::FieldSampler sampler(open);
    std::vector<mesh::Vec3f> inside;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                if (!budget.spend(cost(f))) return inside;
                field::Vec3 p;
                const int g[3] = {i, j, k};
                for (std::size_t a = 0; a < 3; ++a)
                    p[a] = f.box.lo[a] + (f.box.hi[a] - f.box.lo[a]) * (g[a] + 0.5) / n;
                if (sampler.value(p) >= 0)
                    inside.push_back({float(p[0]), float(p[1]), float(p[2])});
            }
    return evenlyPicked(inside, most);
}

std::vector<mesh::Vec3f> evenlyPicked(const std::vector<mesh::Vec3f>& points, std::size_t most) {
    if (points.size() <= most) return points;
    std::vector<mesh::Vec3f> kept;
    for (std::size_t i = 0; i < most; ++i)
        kept.push_back(points[i * points.size() / most]);
    return kept;
}

} // namespace fl::grading
