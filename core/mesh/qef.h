#pragma once
// The quadratic error function of dual contouring (Ju et al. 2002): the point
// that best lies on every tangent plane (p_i, n_i) of the surface crossings in
// a cell. Solved about the crossings' mass point with small eigenvalues
// truncated, so flat and cylindrical cells stay near the mass point while
// corners and creases of min/max set operations come out sharp. Accumulated
// as sums (A^T A, A^T b, the point sum) relative to an origin near the planes
// (the first point, or one the caller sets), so adding a plane is a few
// multiplications and additions and nothing is stored per plane.
#include <array>
#include <cstddef>

namespace fl::mesh {

class Qef {
  public:
    // What one plane (p, n) adds to the sums about an origin o, in the order
    // they are kept: n n^T (xx xy xz yy yz zz), n (n . (p - o)), p - o, n and
    // a count of 1. The mesher makes it once per crossing, about its block's
    // corner, and adds it to the (up to) four cells around: sixteen
    // additions a cell, which the compiler makes vector additions.
    using Plane = std::array<double, 16>;
    static Plane plane(const std::array<double, 3>& origin, const std::array<double, 3>& point,
                       const std::array<double, 3>& normal) {
        const double x = point[0] - origin[0], y = point[1] - origin[1], z = point[2] - origin[2];
        const double d = normal[0] * x + normal[1] * y + normal[2] * z;
        return {normal[0] * normal[0],
                normal[0] * normal[1],
                normal[0] * normal[2],
                normal[1] * normal[1],
                normal[1] * normal[2],
                normal[2] * normal[2],
                normal[0] * d,
                normal[1] * d,
                normal[2] * d,
                x,
                y,
                z,
                normal[0],
                normal[1],
                normal[2],
                1.0};
    }
    // Sums about the first point added.
    void add(const std::array<double, 3>& point, const std::array<double, 3>& normal) {
        if (count() == 0) origin_ = point;
        add(plane(origin_, point, normal));
    }
    // A plane made about this Qef's origin (see reset).
    void add(const Plane& plane) {
        for (std::size_t k = 0; k < sums_.size(); ++k)
            sums_[k] += plane[k];
    }
    int count() const { return int(sums_[kCount]); }
    // Empty again, its sums about `origin` (add(point, normal) sets the
    // origin to its first point instead).
    void reset(const std::array<double, 3>& origin) {
        origin_ = origin;
        sums_.fill(0.0);
    }
    std::array<double, 3> massPoint() const;
    // The minimiser; eigenvalues below `relativeCutoff` times the largest are
    // treated as zero (the solution then moves only along the others).
    std::array<double, 3> solve(double relativeCutoff = 0.05) const;
    // The minimiser within the box [lo, hi] (a cell): solve()'s point when it
    // lies there; else the coordinates it leaves the box by are held on the
    // box's faces and the others minimise the QEF again (at most three
    // rounds, each holding one more). A crease that passes just outside the
    // cell puts the vertex on the cell's face nearest it, on both surfaces,
    // where falling back to the mass point left it inside the solid by up to
    // half a cell.
    std::array<double, 3> solveInBox(const std::array<double, 3>& lo,
                                     const std::array<double, 3>& hi,
                                     double relativeCutoff = 0.05) const;

    // The minimiser with the coordinates `held` fixed at `at` (the plane of
    // a closed box's face, or the line or corner where faces meet, which
    // the mesher knows exactly): the free ones minimise the QEF there, their
    // eigenvalues under `relativeCutoff` times the largest of them
    // truncated; then kept in [lo, hi] as solveInBox keeps its point. A
    // shape meeting a face at a shallow angle (under 37 degrees between the
    // normals) has a crease that solve() with the mesher's cutoff cannot
    // see: the vertex stayed between face and surface, a third of a cell
    // from both; on the face plane the crease is the one strong direction.
    std::array<double, 3> solveOnPlanes(const std::array<bool, 3>& held,
                                        const std::array<double, 3>& at,
                                        const std::array<double, 3>& lo,
                                        const std::array<double, 3>& hi,
                                        double relativeCutoff = 0.05) const;

  private:
    // solveInBox's rounds from the point `from` (about origin_), `held`
    // already fixed: each holds the coordinates outside [lo, hi] on the
    // face they left by and minimises again.
    std::array<double, 3> heldInBox(std::array<bool, 3> held, const std::array<double, 3>& from,
                                    const std::array<double, 3>& lo,
                                    const std::array<double, 3>& hi, double relativeCutoff) const;
    static constexpr std::size_t kAta = 0, kAtb = 6, kPointSum = 9, kNormalSum = 12, kCount = 15;
    double sumAtA(std::size_t k) const { return sums_[kAta + k]; } // xx xy xz yy yz zz
    double sumAtb(std::size_t k) const { return sums_[kAtb + k]; }
    double sumPoints(std::size_t k) const { return sums_[kPointSum + k]; } // relative to origin_
    double sumNormals(std::size_t k) const { return sums_[kNormalSum + k]; }
    // What the solvers and massPoint start from: A^T A as a symmetric 3x3
    // matrix (row by row), and the points' mean relative to origin_ (with
    // at least one plane).
    std::array<double, 9> normalMatrix() const {
        return {sumAtA(0), sumAtA(1), sumAtA(2), sumAtA(1), sumAtA(3),
                sumAtA(4), sumAtA(2), sumAtA(4), sumAtA(5)};
    }
    std::array<double, 3> meanOffset() const {
        return {sumPoints(0) / count(), sumPoints(1) / count(), sumPoints(2) / count()};
    }

    std::array<double, 3> origin_{}; // the sums are relative to it
    Plane sums_{};                   // as a Plane lays them out
};

} // namespace fl::mesh
