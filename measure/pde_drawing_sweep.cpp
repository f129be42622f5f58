#include "pde_drawing_sweep.h"

#include "mesh/surface_distance.h"
#include "pde/pde_mesh.h"

#include <algorithm>
#include <chrono>

namespace fl::measure {

std::vector<AccuracyRow> pdeDrawingSweep(const pde::Model& model,
                                         const std::vector<double>& resolutions,
                                         const std::atomic<bool>* cancel,
                                         const std::function<void(const AccuracyRow&)>& row) {
    std::vector<AccuracyRow> rows;
    if (resolutions.empty() || model.patches.empty()) return rows;
    const double finest = *std::max_element(resolutions.begin(), resolutions.end());
    // The reference: twice as fine as any row (its own chordal error a
    // quarter of the finest row's), within the grid bound every meshing keeps.
    const mesh::Mesh reference = pde::meshModel(model, pde::meshOptionsFor(2 * finest));
    const double diagonal = model.diagonal() > 0 ? model.diagonal() : 1.0;
    for (double r : resolutions) {
        if (cancel && cancel->load()) break;
        AccuracyRow out;
        out.method = Method::PdeMesh;
        out.resolution = r;
        mesh::Mesh drawn;
        double best = 1e300;
        for (int run = 0; run < 3; ++run) {
            const auto started = std::chrono::steady_clock::now();
            drawn = pde::meshModel(model, pde::meshOptionsFor(r));
            best = std::min(best, std::chrono::duration<double, std::milli>(
                                      std::chrono::steady_clock::now() - started)
                                      .count());
        }
        out.milliseconds = best;
        out.triangles = drawn.triangleCount();
        const mesh::OneWayDistance d =
            mesh::distanceFrom(reference, mesh::TriangleTree(drawn), 20000);
        out.maxError = d.max / diagonal;
        out.meanError = d.rms / diagonal;
        rows.push_back(out);
        if (row) row(out);
    }
    return rows;
}

} // namespace fl::measure
