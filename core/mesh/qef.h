#pragma once
// The quadratic error function of dual contouring (Ju et al. 2002): the point
// that best lies on every tangent plane (p_i, n_i) of the surface crossings in
// a cell. Solved about the crossings' mass point with small eigenvalues
// truncated, so flat and cylindrical cells stay near the mass point while
// corners and creases of min/max set operations come out sharp.
#include <array>

namespace fl::mesh {

class Qef {
  public:
    void add(const std::array<double, 3>& point, const std::array<double, 3>& normal);
    int count() const { return count_; }
    std::array<double, 3> massPoint() const;
    // The minimiser; eigenvalues below `relativeCutoff` times the largest are
    // treated as zero (the solution then moves only along the others).
    std::array<double, 3> solve(double relativeCutoff = 0.05) const;

  private:
    std::array<double, 3> pointSum_{};
    std::array<std::array<double, 3>, 12> points_{};
    std::array<std::array<double, 3>, 12> normals_{};
    int count_ = 0;
};

} // namespace fl::mesh
