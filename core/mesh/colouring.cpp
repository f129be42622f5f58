#include "colouring.h"

#include "component_mapping.h"
#include "formula/eval_batch.h"

#include <algorithm>
#include <cmath>

namespace fl::mesh {

std::array<double, 3> mapThroughKeys(double value, const std::vector<double>& key,
                                     const std::vector<std::array<double, 3>>& keyValue) {
    const std::size_t n = std::min(key.size(), keyValue.size());
    if (n == 0) return {0.8, 0.8, 0.8};
    if (!(value > key[0])) return keyValue[0];
    if (value >= key[n - 1]) return keyValue[n - 1];
    const auto upper = std::upper_bound(key.begin(), key.begin() + std::ptrdiff_t(n), value);
    const std::size_t i = std::size_t(upper - key.begin()) - 1;
    const double span = key[i + 1] - key[i];
    const double s = span > 0 ? (value - key[i]) / span : 1;
    std::array<double, 3> c{};
    for (std::size_t k = 0; k < 3; ++k)
        c[k] = keyValue[i][k] + s * (keyValue[i + 1][k] - keyValue[i][k]);
    return c;
}

std::vector<std::string> applyColour(Mesh& mesh, const ColourField& field) {
    std::vector<std::string> warnings;
    const std::size_t n = mesh.vertexCount();
    // The component's view of each vertex.
    const std::array<std::vector<double>, 6> in =
        componentViews(mesh, field.geometryBox, field.componentBox);
    auto run = [&](const formula::Tape& tape, std::vector<std::vector<double>>& out) {
        formula::BatchEvaluator e(tape);
        formula::BatchInputs inputs;
        inputs.set(formula::Input::X, in[0].data());
        inputs.set(formula::Input::Y, in[1].data());
        inputs.set(formula::Input::Z, in[2].data());
        inputs.set(formula::Input::U, in[3].data());
        inputs.set(formula::Input::V, in[4].data());
        inputs.set(formula::Input::W, in[5].data());
        inputs.set(formula::Input::T, field.t);
        out.assign(tape.outputs.size(), std::vector<double>(n));
        std::vector<double*> ptrs;
        for (auto& o : out)
            ptrs.push_back(o.data());
        if (n) e.evaluate(inputs, n, ptrs.data());
    };
    std::vector<std::vector<double>> colour, alpha;
    if (field.colour) run(*field.colour, colour);
    if (field.transparency) run(*field.transparency, alpha);
    bool undefined = false;
    mesh.colours.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        std::array<double, 3> rgb = field.fallback;
        if (colour.size() == 3) {
            rgb = {colour[0][i], colour[1][i], colour[2][i]};
        } else if (colour.size() == 1) {
            rgb = std::isnan(colour[0][i])
                      ? rgb
                      : mapThroughKeys(colour[0][i], field.key, field.keyValue);
            if (std::isnan(colour[0][i])) undefined = true;
        }
        for (double& k : rgb) {
            if (std::isnan(k)) {
                undefined = true;
                k = 0.5;
            }
            k = std::clamp(k, 0.0, 1.0);
        }
        double transparency = alpha.empty() ? field.constantTransparency : alpha[0][i];
        if (std::isnan(transparency)) {
            undefined = true;
            transparency = field.constantTransparency;
        }
        mesh.colours[i] = {float(rgb[0]), float(rgb[1]), float(rgb[2]),
                           float(1 - std::clamp(transparency, 0.0, 1.0))};
    }
    if (undefined)
        warnings.push_back("the colour is undefined (NaN) at some vertices; they are shown grey");
    return warnings;
}

} // namespace fl::mesh
