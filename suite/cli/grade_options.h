#pragma once
// What the `grade` commands share: their --assignment and --db options
// (one wording in every command's help), finding the assignment with its
// located problems printed, and refusing a gradebook that is not there.
#include "platform/option_table.h"

#include "courseware/assignment.h"
#include "grading/gradebook.h"

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

// --signing-key FILE: the instructor's secret key that signs the gradebook's
// log (grading/signing.h); without it, FUNCTIONLAB_GRADING_KEY or
// ~/.config/functionlab/grading.key when there is one.
OptionSpec signingKeyOption();

// Signs the gradebook's head with that key and says so on `err`; without a
// key, says the head stays unsigned. Nullopt when it was not signed (a key
// that cannot be read is said too).
std::optional<grading::SignedHead> signHeadOrSay(grading::Gradebook& book, const ParsedArgs& a,
                                                 const std::string& command, std::ostream& err);

// The head as exports carry it: one JSON object {"entry", "hash",
// "publicKey", "signature"} (the last two null when unsigned).
std::string headJson(const grading::LogHead& head, const std::optional<grading::SignedHead>& s);

} // namespace fl::cli
