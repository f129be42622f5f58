#pragma once
// What a submission is, for the gradebook: a SHA-256 over its bytes — a
// scene file, or every file of a submission folder with its relative path —
// so a batch run again skips what it has graded, and a grade row says exactly
// which submission it judged.
#include <filesystem>
#include <optional>
#include <string>

namespace fl::grading {

// None when it cannot be read (or a folder holds more than 10 000 files or
// 1 GiB: not a submission).
std::optional<std::string> submissionHash(const std::filesystem::path& path);

} // namespace fl::grading
