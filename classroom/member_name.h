#pragma once
// What a member of a class may be called (issue 26 §2). A name is shown in
// every window of the class, so it must read as what it is: no control
// characters, no bidirectional controls that reorder the text around it, no
// spaces at either end, at least one visible character, not the name of a
// role or of the anonymous aliases ("Instructor", "Learner 3"), and not a
// name another member already has once both are normalised (NFC) and
// case-folded. Lengths count characters, not bytes or UTF-16 units.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace fl::classroom {

// Why `name` (UTF-8) cannot be a member's name; nothing when it can.
std::optional<std::string> memberNameProblem(std::string_view name, std::size_t maxChars);

// The form two names are compared in: "Ada", "ADA" and "ada" are one name,
// and so are an "é" written as one character or as "e" and an accent.
std::string memberNameKey(std::string_view name);

// Characters (Unicode code points) in UTF-8 text.
std::size_t characterCount(std::string_view utf8);

} // namespace fl::classroom
