#pragma once
// Parametric geometry: x, y, z as functions of the parameters u, v, w (and t),
// sampled on parameter lines placed adaptively (parameter_lines.h).
// What the definition reads decides what it is: one parameter a curve (meshed
// as a thin tube), two a surface, three a solid (its six boundary faces).
// Seams and poles — where different parameters reach the same point, as a
// sphere's u = 0 and u = 2 pi, or its whole v = 0 row — are welded, the
// degenerate triangles they leave dropped, and normals there taken from the
// surrounding triangles, so none is zero or NaN.
#include "dual_contouring.h" // MeshResult, MeshStats
#include "formula/eval_batch.h"
#include "formula/eval_gradient.h"
#include "formula/tape.h"
#include "mesh.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace fl::mesh {

struct ParametricField {
    formula::Tape tape;                                                    // outputs x, y, z
    std::array<std::array<double, 2>, 3> ranges{{{0, 1}, {0, 1}, {0, 1}}}; // u, v, w
    double t = 0;
    std::vector<std::pair<std::string, double>> parameters;
    // The box the object is expected to lie in: sizes the curve's tube.
    Box3 box;
};

struct ParametricOptions {
    // Uniform: segments along each parameter. Adaptive: the detail asked for
    // — the parameter lines start a quarter as dense and are halved where the
    // object strays from its chords, up to four times as dense.
    double resolution = 32;
    bool adaptive = true;
    // Adaptive: the chord error allowed, in the units of x, y, z; 0 picks 2%
    // of a cell (the box's longest side / resolution).
    double tolerance = 0;
    double tubeRadius = 0; // curves: 0 picks 1% of the box diagonal
    int tubeSides = 8;
};

// The mesh carries each vertex's (u, v, w) in Mesh::parameters.
MeshResult meshParametric(const ParametricField& field, const ParametricOptions& options = {});

// The parameters (0 = u, 1 = v, 2 = w) the definition reads, or an error
// (empty when none) when the field cannot be sampled: not three outputs, or
// a used range that does not go from low to high.
std::vector<int> usedParameters(const ParametricField& field, std::string& error);

// x, y, z and their partial derivatives at parameter points, with the
// field's named parameters and t applied.
class ParametricSampler {
  public:
    explicit ParametricSampler(const ParametricField& field);
    // x, y, z at `count` points given as u, v, w arrays (resized to count).
    void positions(const std::array<std::vector<double>, 3>& uvw, std::size_t count,
                   std::array<std::vector<double>, 3>& xyz);
    // x, y, z with their derivatives along u, v, w at one point.
    void partials(double u, double v, double w, formula::Dual out[3]);

  private:
    double t_;
    formula::BatchEvaluator batch_;
    formula::GradientEvaluator gradient_;
};

} // namespace fl::mesh
