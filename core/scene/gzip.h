#pragma once
// gzip decoding for .x3d.gz, .x3dvz, .wrl.gz ... with a bound on the output,
// so a small "zip bomb" cannot take the machine's memory.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace fl::scene {

bool isGzip(std::string_view bytes);

// The decoded bytes, or nullopt with `problem` set (corrupt data, or more
// than `maxBytes` of output).
std::optional<std::string> gunzip(std::string_view bytes, std::size_t maxBytes,
                                  std::string& problem);

std::string gzip(std::string_view bytes);

} // namespace fl::scene
