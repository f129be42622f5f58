#pragma once
// The shape a meshing benchmark measures: the first implicit or explicit
// FGeometry of a scene (bench accuracy, bench mesh).
#include "field/field_sampler.h"

#include <string>

namespace fl::cli {

// False, with the reason on stderr (naming `command`), when the scene cannot
// be read or has no such geometry; `name` says which one was taken.
bool benchFieldFromScene(const std::string& command, const std::string& file,
                         field::ImplicitField& field, std::string& name);

} // namespace fl::cli
