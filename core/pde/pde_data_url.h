#pragma once
// A PDE model carried inside a scene: a `data:` url holding the binary .pde
// file in base64 (RFC 2397), so a scene stands alone — a class scene, which
// may name no file, can still show a PDE shape (the paper shared its class
// scenes "by broadcasting small function models").
#include "pde_file.h"

#include <optional>
#include <string>
#include <string_view>

namespace fl::pde {

inline constexpr std::string_view kPdeMediaType = "application/x-functionlab-pde";

bool isDataUrl(std::string_view url);
std::string dataUrlOf(const Model& model, const EncodeOptions& options = {});
// The model a data url holds; `error` says why not (not base64, too long, not a model).
ReadResult readDataUrl(std::string_view url, std::string_view name);

} // namespace fl::pde
