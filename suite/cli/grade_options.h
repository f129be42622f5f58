#pragma once
// What the `grade` commands share: their --assignment and --db options
// (one wording in every command's help), finding the assignment with its
// located problems printed, and refusing a gradebook that is not there.
#include "cli/option_table.h"

#include "assignment.h"

#include <iosfwd>
#include <optional>
#include <string>

namespace fl::cli {

OptionSpec assignmentOption();
OptionSpec gradebookOption(std::string_view help = "the gradebook");

// The assignment named by an id or a folder; its problems go to `err`.
std::optional<courseware::Assignment> assignmentOrExplain(const std::string& idOrFolder,
                                                          std::ostream& err);

// False (after saying so on `err`) when `path` is no gradebook file.
bool gradebookExists(const std::string& command, const std::string& path, std::ostream& err);

} // namespace fl::cli
