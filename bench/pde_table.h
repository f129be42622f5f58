#pragma once
// `functionlab bench pde`: a PDE model of a mesh against Draco and against
// meshoptimizer's simplifier followed by Draco — bytes, and error measured
// by one code (core/mesh/surface_distance) for every row.
#include <cstddef>
#include <string>
#include <vector>

namespace fl::bench {

struct PdeRow {
    std::string method;  // "pde", "draco", "simplify+draco", "obj", "paper"
    std::string setting; // "40 patches", "qp 11", "error 0.002" ...
    std::size_t bytes = 0;
    double rms = -1, hausdorff = -1; // fractions of the diagonal; < 0: not measured
    double milliseconds = 0;         // to make it (fit, or encode)
};

struct PdeBenchOptions {
    std::vector<double> patches{10, 20, 40, 80};
    std::size_t radii = 8;
    std::vector<double> dracoBits{7, 8, 10, 11, 14};
    std::vector<double> simplifyErrors{0.001, 0.002, 0.005, 0.01};
    std::size_t samples = 100000;
};

// Empty, with `why`, when the mesh cannot be read.
std::vector<PdeRow> runPdeBench(const std::string& meshPath, const PdeBenchOptions& options,
                                std::string& why);
std::string formatPdeTable(const std::string& mesh, const std::vector<PdeRow>& rows);
std::string pdeRowsJson(const std::string& mesh, const std::vector<PdeRow>& rows);
// Bytes against RMS error, log-log, one line per method (the paper's rows have no error).
std::string pdePlotSvg(const std::string& mesh, const std::vector<PdeRow>& rows);

} // namespace fl::bench
