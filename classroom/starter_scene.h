#pragma once
// The scene a class starts with when the teacher names none: one function
// shape, CLASS, that the chat commands and tools work on.
#include <string>

namespace fl::classroom {

std::string starterScene();

} // namespace fl::classroom
