#pragma once
// One number of a field value as both encodings write it: decimal or 0x hex
// integers, decimal floats with an exponent, true/false (or TRUE/FALSE) for
// SFBool. Never "inf" or "nan".
#include "field_type.h"

#include <string>
#include <string_view>

namespace fl::scene {

// Reads `token` as one number of an element of type `single`; false with
// `problem` set when it is not one.
bool parseNumberText(std::string_view token, FieldType single, double& out, std::string& problem);

} // namespace fl::scene
