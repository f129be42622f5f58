#include "parameter_lines.h"

#include <algorithm>
#include <cmath>

namespace fl::mesh {
namespace {

using Point = std::array<double, 3>;

std::vector<double> uniform(const std::array<double, 2>& range, int segments) {
    std::vector<double> lines(std::size_t(segments) + 1);
    for (int i = 0; i <= segments; ++i)
        lines[std::size_t(i)] = range[0] + (range[1] - range[0]) * double(i) / segments;
    lines.back() = range[1]; // exactly, so a seam's two ends are the range's ends
    return lines;
}

// The points across which axis `a` is measured: every combination of the
// other used parameters' lines (for a solid, only those on its faces).
std::vector<Point> crossSamples(int a, const std::vector<int>& used,
                                const std::array<std::vector<double>, 3>& lines) {
    std::vector<int> others;
    for (int p : used)
        if (p != a) others.push_back(p);
    Point base{lines[0].front(), lines[1].front(), lines[2].front()};
    std::vector<Point> out;
    if (others.empty()) {
        out.push_back(base);
    } else if (others.size() == 1) {
        for (double s : lines[std::size_t(others[0])]) {
            Point q = base;
            q[std::size_t(others[0])] = s;
            out.push_back(q);
        }
    } else {
        const auto& lb = lines[std::size_t(others[0])];
        const auto& lc = lines[std::size_t(others[1])];
        for (std::size_t j = 0; j < lc.size(); ++j)
            for (std::size_t i = 0; i < lb.size(); ++i) {
                const bool onFace = i == 0 || j == 0 || i + 1 == lb.size() || j + 1 == lc.size();
                if (!onFace) continue;
                Point q = base;
                q[std::size_t(others[0])] = lb[i];
                q[std::size_t(others[1])] = lc[j];
                out.push_back(q);
            }
    }
    return out;
}

// The chord error of every interval of axis a's lines: the largest distance,
// over the cross samples, of the points at 1/4, 1/2 and 3/4 of the interval
// from the chord between its ends (three, so an S-shaped span, whose middle
// lies on its chord, is still seen).
std::vector<double> deviations(int a, const std::vector<double>& la,
                               const std::vector<Point>& cross, const EvaluateUvw& evaluate,
                               std::size_t& evaluations) {
    static constexpr double kFractions[3] = {0.25, 0.5, 0.75};
    const std::size_t segments = la.size() - 1;
    const std::size_t perCross = la.size() + 3 * segments;
    const std::size_t count = perCross * cross.size();
    std::array<std::vector<double>, 3> uvw;
    for (auto& v : uvw)
        v.resize(count);
    std::size_t n = 0;
    auto put = [&](const Point& c, double s) {
        for (std::size_t k = 0; k < 3; ++k)
            uvw[k][n] = c[k];
        uvw[std::size_t(a)][n] = s;
        ++n;
    };
    for (const Point& c : cross) {
        for (double s : la)
            put(c, s);
        for (std::size_t j = 0; j < segments; ++j)
            for (double f : kFractions)
                put(c, la[j] + f * (la[j + 1] - la[j]));
    }
    std::array<std::vector<double>, 3> xyz;
    evaluate(uvw, count, xyz);
    evaluations += count;
    std::vector<double> worst(segments, 0.0);
    for (std::size_t c = 0; c < cross.size(); ++c) {
        const std::size_t base = c * perCross;
        auto at = [&](std::size_t i) {
            return Point{xyz[0][base + i], xyz[1][base + i], xyz[2][base + i]};
        };
        for (std::size_t j = 0; j < segments; ++j) {
            const Point p0 = at(j), p1 = at(j + 1);
            for (int q = 0; q < 3; ++q) {
                const Point m = at(la.size() + 3 * j + std::size_t(q));
                const double f = kFractions[q];
                double d2 = 0;
                for (std::size_t k = 0; k < 3; ++k) {
                    const double d = m[k] - ((1 - f) * p0[k] + f * p1[k]);
                    d2 += d * d;
                }
                // NaN (undefined there) never asks for a split.
                if (d2 > worst[j] * worst[j]) worst[j] = std::sqrt(d2);
            }
        }
    }
    return worst;
}

} // namespace

ParameterLines parameterLines(const std::vector<int>& used,
                              const std::array<std::array<double, 2>, 3>& ranges,
                              const ParameterLineOptions& options, const EvaluateUvw& evaluate) {
    ParameterLines out;
    const int maxSegments = std::max(1, options.maxSegments);
    const bool adaptive = options.tolerance > 0;
    const int base = std::clamp(options.baseSegments, 1, maxSegments);
    for (std::size_t p = 0; p < 3; ++p)
        out.lines[p] = {ranges[p][0]};
    for (int p : used)
        out.lines[std::size_t(p)] = uniform(ranges[std::size_t(p)], base);
    if (!adaptive) return out;

    // The grid of one face (the two largest line counts) stays in budget.
    auto faceSamples = [&] {
        std::vector<std::size_t> sizes;
        for (int p : used)
            sizes.push_back(out.lines[std::size_t(p)].size());
        std::sort(sizes.rbegin(), sizes.rend());
        return sizes.size() == 1 ? sizes[0] : sizes[0] * sizes[1];
    };
    for (int level = 0; level < 16; ++level) {
        bool split = false;
        for (int a : used) {
            std::vector<double>& la = out.lines[std::size_t(a)];
            const std::vector<Point> cross = crossSamples(a, used, out.lines);
            const std::vector<double> dev = deviations(a, la, cross, evaluate, out.evaluations);
            std::vector<double> refined{la.front()};
            std::size_t segments = la.size() - 1;
            for (std::size_t j = 0; j + 1 < la.size(); ++j) {
                const double mid = la[j] + 0.5 * (la[j + 1] - la[j]);
                // Halving stops where the parameter itself can no longer be split.
                if (dev[j] > options.tolerance && segments < std::size_t(maxSegments) &&
                    mid > la[j] && mid < la[j + 1]) {
                    refined.push_back(mid);
                    ++segments;
                    split = true;
                }
                refined.push_back(la[j + 1]);
            }
            const std::vector<double> before = la;
            la = std::move(refined);
            if (faceSamples() > options.maxGridSamples) {
                la = before;
                return out; // the budget ends the refinement; worstDeviation stays unmeasured
            }
        }
        if (!split) break;
    }
    // What the final lines achieve, measured the same way.
    for (int a : used) {
        const auto dev = deviations(a, out.lines[std::size_t(a)], crossSamples(a, used, out.lines),
                                    evaluate, out.evaluations);
        for (double d : dev)
            out.worstDeviation = std::max(out.worstDeviation, d);
    }
    return out;
}

} // namespace fl::mesh
