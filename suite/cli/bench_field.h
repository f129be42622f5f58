#pragma once
// The shape a meshing benchmark measures: the first implicit or explicit
// FGeometry of a scene (bench accuracy, bench mesh).
#include "field/field_sampler.h"
#include "platform/option_table.h"

#include <optional>
#include <string>

namespace fl::cli {

// False, with the reason on stderr (naming `command`), when the scene cannot
// be read or has no such geometry; `name` says which one was taken.
bool benchFieldFromScene(const std::string& command, const std::string& file,
                         field::ImplicitField& field, std::string& name);

// The shape a command names: the scene FILE's (as above) or --formula over
// --box. None with `exitCode` set (2 for a usage error, said against
// `spec`; 1 for a scene or formula with errors, said on stderr).
std::optional<field::ImplicitField> benchFieldFromArgs(const CommandSpec& spec,
                                                       const ParsedArgs& args, std::string& name,
                                                       int& exitCode);

} // namespace fl::cli
