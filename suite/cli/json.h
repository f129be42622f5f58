#pragma once
// Minimal JSON writing for command-line output (numbers, strings, arrays).
#include "text/json_text.h"

namespace fl::cli {

using text::jsonNumber;
using text::jsonString;

} // namespace fl::cli
