#pragma once
// The quadratic error function of dual contouring (Ju et al. 2002): the point
// that best lies on every tangent plane (p_i, n_i) of the surface crossings in
// a cell. Solved about the crossings' mass point with small eigenvalues
// truncated, so flat and cylindrical cells stay near the mass point while
// corners and creases of min/max set operations come out sharp. Accumulated
// as sums (A^T A, A^T b, the point sum) relative to the first point, so adding
// a plane is a few multiplications and nothing is stored per plane.
#include <array>
#include <cstddef>

namespace fl::mesh {

class Qef {
  public:
    // A normal's products n n^T (xx xy xz yy yz zz): the mesher adds each
    // crossing's plane to up to four cells and makes them once.
    using Products = std::array<double, 6>;
    static Products productsOf(const std::array<double, 3>& n) {
        return {n[0] * n[0], n[0] * n[1], n[0] * n[2], n[1] * n[1], n[1] * n[2], n[2] * n[2]};
    }
    // Inline: the mesher adds about four planes a vertex.
    void add(const std::array<double, 3>& point, const std::array<double, 3>& normal) {
        add(point, normal, productsOf(normal));
    }
    void add(const std::array<double, 3>& point, const std::array<double, 3>& normal,
             const Products& products) {
        if (count_ == 0) origin_ = point;
        const double x = point[0] - origin_[0], y = point[1] - origin_[1],
                     z = point[2] - origin_[2];
        const double d = normal[0] * x + normal[1] * y + normal[2] * z;
        for (std::size_t k = 0; k < 6; ++k)
            ata_[k] += products[k];
        atb_[0] += normal[0] * d;
        atb_[1] += normal[1] * d;
        atb_[2] += normal[2] * d;
        pointSum_[0] += x;
        pointSum_[1] += y;
        pointSum_[2] += z;
        normalSum_[0] += normal[0];
        normalSum_[1] += normal[1];
        normalSum_[2] += normal[2];
        ++count_;
    }
    int count() const { return count_; }
    // Empty again (as a new Qef: add() sets the origin).
    void reset() {
        ata_ = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        atb_ = {0.0, 0.0, 0.0};
        pointSum_ = {0.0, 0.0, 0.0};
        normalSum_ = {0.0, 0.0, 0.0};
        count_ = 0;
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

  private:
    std::array<double, 3> origin_{}; // the first point: sums are relative to it
    std::array<double, 6> ata_{};    // xx xy xz yy yz zz
    std::array<double, 3> atb_{};
    std::array<double, 3> pointSum_{}; // relative to origin_
    std::array<double, 3> normalSum_{};
    int count_ = 0;
};

} // namespace fl::mesh
