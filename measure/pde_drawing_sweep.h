#pragma once
// What drawing a PDE model costs (issue 30 §4, the Accuracy panel's curve
// for an FPdeSurface): the model meshed at each resolution as the scene's
// meshers do (pde::meshOptionsFor), timed, and measured against its finest
// drawing — every vertex and area-weighted samples of a mesh at twice the
// finest resolution swept, at their exact distance to the coarser mesh.
#include "accuracy_sweep.h"
#include "pde/pde_model.h"

#include <atomic>
#include <functional>
#include <vector>

namespace fl::measure {

// Rows of Method::PdeMesh, in the order of `resolutions`: milliseconds to
// mesh (the least of three runs), triangles, max and RMS error (meanError)
// as fractions of the model's diagonal. `row` (when given) hears each as it
// is made; `cancel` stops the sweep between rows.
std::vector<AccuracyRow> pdeDrawingSweep(const pde::Model& model,
                                         const std::vector<double>& resolutions,
                                         const std::atomic<bool>* cancel = nullptr,
                                         const std::function<void(const AccuracyRow&)>& row = {});

} // namespace fl::measure
