#pragma once
// Whether two scenes hold the same model: the same nodes with the same fields
// and values, the same sharing (DEF/USE), ROUTEs, PROTO declarations and kept
// statements. Source positions and the encoding are not part of the model.
#include "scene.h"

#include <string>

namespace fl::scene {

// True when equal; otherwise false with `difference` saying where they part.
bool sameModel(const Scene& a, const Scene& b, std::string* difference = nullptr);

} // namespace fl::scene
