// libFuzzer target: a Wavefront OBJ mesh from anyone (pde fit's input).
// Beyond "no crash, no hang": a mesh that reads has finite positions and
// in-range indices, every error is located, and the PDE fit of a small one
// either succeeds or says why (never crashes on its topology).
#include "mesh/obj_reader.h"
#include "pde/mesh_fit.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    const auto r = fl::mesh::readObj(bytes, "fuzz.obj");
    if (!r.ok()) {
        if (r.error.rfind("fuzz.obj", 0) != 0) std::abort();
        return 0;
    }
    for (const auto& p : r.mesh->positions)
        for (float c : p)
            if (!std::isfinite(c)) std::abort();
    for (const auto& t : r.mesh->triangles)
        for (auto i : t)
            if (i >= r.mesh->positions.size()) std::abort();
    if (r.mesh->triangles.size() <= 64) {
        fl::pde::MeshFitOptions o;
        o.patches = 2;
        o.radii = 2;
        std::string why;
        const auto fit = fl::pde::fitMesh(*r.mesh, o, &why, &r.triangleLines);
        if (!fit && why.empty()) std::abort();
    }
    return 0;
}
