#include "planar_fill.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace fl::mesh {
namespace {

// One non-horizontal contour edge, lower end first; `winding` +1 when the
// contour runs upwards along it.
struct Edge {
    double x0, y0, x1, y1;
    int winding;
};

// Exact at the ends, so two edges meeting at a vertex give the same x there
// and a line's break points are shared bit for bit by the slabs on both sides.
double xAt(const Edge& e, double y) {
    if (y == e.y0) return e.x0;
    if (y == e.y1) return e.x1;
    return e.x0 + (e.x1 - e.x0) * ((y - e.y0) / (e.y1 - e.y0));
}

std::vector<Edge> edgesOf(const std::vector<Contour2>& contours) {
    std::vector<Edge> edges;
    for (const Contour2& raw : contours) {
        Contour2 c;
        for (const Point2& p : raw)
            if (std::abs(p[0]) <= 1e150 && std::abs(p[1]) <= 1e150) c.push_back(p); // NaN fails too
        if (c.size() < 3) continue;
        for (std::size_t i = 0; i < c.size(); ++i) {
            const Point2& a = c[i];
            const Point2& b = c[(i + 1) % c.size()];
            if (a[1] == b[1]) continue; // horizontal: adds no winding
            if (a[1] < b[1])
                edges.push_back({a[0], a[1], b[0], b[1], +1});
            else
                edges.push_back({b[0], b[1], a[0], a[1], -1});
        }
    }
    std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.y0 < b.y0; });
    return edges;
}

// Every height where the inside can change: vertices, crossings of two
// edges, and the grid's rows within the contours' extent.
std::vector<double> slabLines(const std::vector<Edge>& edges, const FillGrid& grid,
                              std::string& problem) {
    std::vector<double> ys;
    double lo = INFINITY, hi = -INFINITY;
    for (const Edge& e : edges) {
        ys.push_back(e.y0);
        ys.push_back(e.y1);
        lo = std::min(lo, e.y0);
        hi = std::max(hi, e.y1);
    }
    for (double y : grid.ys)
        if (y > lo && y < hi) ys.push_back(y);
    long long tests = 0;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const Edge& a = edges[i];
        for (std::size_t j = i + 1; j < edges.size() && edges[j].y0 < a.y1; ++j) {
            if (++tests > kMaxFillPairTests) {
                problem = "an outline of " + std::to_string(edges.size()) +
                          " edges is too complex to fill";
                return {};
            }
            const Edge& b = edges[j];
            const double yLo = std::max(a.y0, b.y0), yHi = std::min(a.y1, b.y1);
            if (yHi <= yLo) continue;
            const double dLo = xAt(a, yLo) - xAt(b, yLo), dHi = xAt(a, yHi) - xAt(b, yHi);
            if (dLo * dHi >= 0) continue; // apart, or touching only at an end
            const double y = yLo + (yHi - yLo) * (dLo / (dLo - dHi));
            if (y > yLo && y < yHi) ys.push_back(y);
        }
    }
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
    return ys;
}

// The points on one slab line: where edges meet it and where grid columns
// cross it; made into output points only when a filled span uses them.
struct LinePoints {
    double y = 0;
    std::vector<double> xs;
    std::vector<std::int64_t> index; // -1 until used
};

class Filler {
  public:
    Filler(PlanarFill& out, const std::vector<double>& gridXs) : out_(out), gridXs_(gridXs) {}

    LinePoints line(double y, const std::vector<const Edge*>& touching) const {
        LinePoints l;
        l.y = y;
        for (const Edge* e : touching)
            l.xs.push_back(xAt(*e, y));
        double lo = INFINITY, hi = -INFINITY;
        for (double x : l.xs) {
            lo = std::min(lo, x);
            hi = std::max(hi, x);
        }
        const auto first = std::upper_bound(gridXs_.begin(), gridXs_.end(), lo);
        const auto last = std::lower_bound(first, gridXs_.end(), hi);
        l.xs.insert(l.xs.end(), first, last);
        std::sort(l.xs.begin(), l.xs.end());
        l.xs.erase(std::unique(l.xs.begin(), l.xs.end()), l.xs.end());
        l.index.assign(l.xs.size(), -1);
        return l;
    }

    // The indices of the line's points from xLeft to xRight (both on it).
    std::vector<std::uint32_t> run(LinePoints& l, double xLeft, double xRight) {
        std::vector<std::uint32_t> out;
        auto first = std::lower_bound(l.xs.begin(), l.xs.end(), xLeft);
        for (auto it = first; it != l.xs.end() && *it <= xRight; ++it) {
            const std::size_t k = std::size_t(it - l.xs.begin());
            if (l.index[k] < 0) {
                l.index[k] = std::int64_t(out_.points.size());
                out_.points.push_back({*it, l.y});
            }
            out.push_back(std::uint32_t(l.index[k]));
        }
        return out;
    }

    // Triangles between a span's bottom and top runs, advancing along
    // whichever side is behind so the diagonals stay short.
    void zip(const std::vector<std::uint32_t>& bottom, const std::vector<std::uint32_t>& top) {
        if (bottom.empty() || top.empty()) return;
        std::size_t i = 0, j = 0;
        while (i + 1 < bottom.size() || j + 1 < top.size()) {
            const bool advanceBottom =
                i + 1 < bottom.size() &&
                (j + 1 >= top.size() || out_.points[bottom[i + 1]][0] < out_.points[top[j + 1]][0]);
            if (advanceBottom) {
                out_.triangles.push_back({bottom[i], bottom[i + 1], top[j]});
                ++i;
            } else {
                out_.triangles.push_back({bottom[i], top[j + 1], top[j]});
                ++j;
            }
        }
    }

  private:
    PlanarFill& out_;
    const std::vector<double>& gridXs_;
};

bool inside(int winding, FillRule rule) {
    return rule == FillRule::EvenOdd ? (winding % 2) != 0 : winding != 0;
}

} // namespace

double signedArea2(const Contour2& c) {
    double a = 0;
    for (std::size_t i = 0; i < c.size(); ++i) {
        const Point2& p = c[i];
        const Point2& q = c[(i + 1) % c.size()];
        a += p[0] * q[1] - q[0] * p[1];
    }
    return a;
}

PlanarFill fillContours(const std::vector<Contour2>& contours, FillRule rule,
                        const FillGrid& grid) {
    PlanarFill out;
    const std::vector<Edge> edges = edgesOf(contours);
    if (edges.empty()) return out;
    const std::vector<double> ys = slabLines(edges, grid, out.problem);
    if (ys.empty()) return out;
    std::vector<double> gridXs = grid.xs;
    std::sort(gridXs.begin(), gridXs.end());
    Filler filler(out, gridXs);

    std::size_t nextEdge = 0;
    std::vector<const Edge*> open; // edges with y0 <= y <= y1 at the current line
    auto touching = [&](double y) -> const std::vector<const Edge*>& {
        while (nextEdge < edges.size() && edges[nextEdge].y0 <= y)
            open.push_back(&edges[nextEdge++]);
        std::erase_if(open, [&](const Edge* e) { return e->y1 < y; });
        return open;
    };

    LinePoints bottom = filler.line(ys[0], touching(ys[0]));
    struct Crossing {
        double xBottom, xTop;
        int winding;
    };
    std::vector<Crossing> crossings;
    for (std::size_t k = 0; k + 1 < ys.size(); ++k) {
        const double y0 = ys[k], y1 = ys[k + 1];
        crossings.clear();
        for (const Edge* e : open)
            if (e->y0 <= y0 && e->y1 >= y1)
                crossings.push_back({xAt(*e, y0), xAt(*e, y1), e->winding});
        std::sort(crossings.begin(), crossings.end(), [](const Crossing& a, const Crossing& b) {
            const double ma = a.xBottom + a.xTop, mb = b.xBottom + b.xTop;
            return ma != mb ? ma < mb : a.xBottom < b.xBottom;
        });
        LinePoints top = filler.line(y1, touching(y1));
        int winding = 0;
        for (std::size_t i = 0; i + 1 < crossings.size(); ++i) {
            winding += crossings[i].winding;
            if (!inside(winding, rule)) continue;
            const Crossing& l = crossings[i];
            const Crossing& r = crossings[i + 1];
            if (out.points.size() > kMaxFillPoints) {
                out = PlanarFill{};
                out.problem = "filling these outlines would take more than " +
                              std::to_string(kMaxFillPoints) + " points";
                return out;
            }
            // At a crossing the two edges' xs may come out a rounding error
            // the wrong way round: the span is then a point wide there.
            filler.zip(
                filler.run(bottom, std::min(l.xBottom, r.xBottom), std::max(l.xBottom, r.xBottom)),
                filler.run(top, std::min(l.xTop, r.xTop), std::max(l.xTop, r.xTop)));
        }
        bottom = std::move(top);
    }
    return out;
}

} // namespace fl::mesh
