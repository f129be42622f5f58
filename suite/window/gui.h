#pragma once
// Starting the window: `functionlab` with no arguments (the watermelon
// example, or unsaved work from last time) or with a scene file.
#include "classroom/protocol.h"
#include "platform/option_table.h"

#include <optional>
#include <string>
#include <vector>

namespace fl::suite {

// `functionlab --join ws://HOST:P --class CODE --name NAME [--role ROLE]
// [--key KEY]`: the window opens and joins that class.
struct JoinRequest {
    std::string url, classCode, name;
    classroom::Role role = classroom::Role::Student;
    std::string key;
};
// Its options, on the shared table (help, checks, "did you mean").
const cli::CommandSpec& joinSpec();
// The request, or none with what is wrong in `error` (empty: the arguments
// are not a join at all).
std::optional<JoinRequest> parseJoinArguments(const std::vector<std::string>& args,
                                              std::string& error);

// Runs the window until it is closed; returns the exit code. `file` empty:
// the recovery file if there is one, else the watermelon example.
int runWindow(int argc, char** argv, const std::string& file,
              const std::optional<JoinRequest>& join = std::nullopt);

// Whether an argument names a scene to open rather than a command.
bool looksLikeSceneFile(const std::string& argument);

} // namespace fl::suite
