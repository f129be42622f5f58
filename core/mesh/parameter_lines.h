#pragma once
// Where a parametric object is sampled: per parameter, the values (lines) at
// which its tessellation grid is cut — uniform, or adaptive: an interval is
// halved while the object across it strays from its chord by more than a
// tolerance anywhere it is drawn. There is one set of lines per parameter,
// shared by every row and every face, so neighbouring rows, the two sides of
// a seam and the faces of a solid always meet vertex to vertex: no cracks and
// no T-junctions, whatever was refined.
#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace fl::mesh {

struct ParameterLineOptions {
    int baseSegments = 8;  // uniform segments per parameter to start from
    int maxSegments = 128; // never more than this per parameter
    double tolerance = 0;  // chord error allowed (units of x, y, z); <= 0: uniform
    std::size_t maxGridSamples = std::size_t(1) << 22; // grid vertices of one face at most
};

// x, y, z at `count` parameter points (u, v, w arrays); NaN where undefined.
using EvaluateUvw = std::function<void(const std::array<std::vector<double>, 3>& uvw,
                                       std::size_t count, std::array<std::vector<double>, 3>& xyz)>;

struct ParameterLines {
    std::array<std::vector<double>, 3> lines; // an unused parameter: its low end only
    std::size_t evaluations = 0;              // points evaluated to place them
    double worstDeviation = 0;                // the largest chord error measured on the final lines
};

// `used`: the parameters (0 = u, 1 = v, 2 = w) the definition reads. A solid
// (three used) is drawn by its boundary, so only its faces are measured.
ParameterLines parameterLines(const std::vector<int>& used,
                              const std::array<std::array<double, 2>, 3>& ranges,
                              const ParameterLineOptions& options, const EvaluateUvw& evaluate);

} // namespace fl::mesh
