#pragma once
// Per-vertex colour from an FMaterial: a parametric colour (r, g, b assigned)
// or an explicit function whose value is mapped through key values to colours
// (linear interpolation), each read in the material's own domain box mapped
// onto the geometry's (docs/nodes.md, "Domains and how they are mapped").
#include "field_names.h"
#include "mesh.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace fl::mesh {

struct ColourField {
    std::optional<formula::Tape> colour;       // r, g, b, or one value for the key map
    std::optional<formula::Tape> transparency; // one value in [0, 1]
    std::vector<double> key;                   // for a one-value colour
    std::vector<std::array<double, 3>> keyValue;
    Box3 geometryBox;  // where the mesh lives
    Box3 componentBox; // the material's own box
    double t = 0;
    std::array<double, 3> fallback{0.8, 0.8, 0.8}; // diffuseColor: where there is no formula
    double constantTransparency = 0;
};

// Fills mesh.colours (RGBA in [0, 1]). For parametric geometry (mesh.parameters
// set) u, v, w are the surface's own parameters; otherwise the point's place in
// the geometry's box. Returns warnings (undefined colours, each said once).
std::vector<std::string> applyColour(Mesh& mesh, const ColourField& field);

// A value through key/keyValue: linear between neighbouring keys, clamped at the ends.
std::array<double, 3> mapThroughKeys(double value, const std::vector<double>& key,
                                     const std::vector<std::array<double, 3>>& keyValue);

} // namespace fl::mesh
