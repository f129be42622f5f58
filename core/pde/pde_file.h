#pragma once
// The .pde file: a PDE model in a few kilobytes (docs/pde.md has the byte
// layout). Binary: an 8-byte header ("FLPDE", 0, version, 0), the payload's
// size, then the payload compressed with zlib — the box, the quantisation
// step, and every patch's radii, a and coefficients as whole multiples of
// the step (zigzag varints, so the small high-frequency coefficients take a
// byte or two). Text (`pde fit --text`): the same model, one line per mode,
// exact decimal numbers, for a student to read.
//
// Read from others: every count is checked against the bytes that remain
// before anything is allocated, the payload's size is bounded before it is
// inflated, and every mistake is located (a byte offset in the binary form,
// line:column in the text form).
#include "pde_model.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace fl::pde {

inline constexpr std::size_t kMaxFileBytes = 64u << 20;     // 64 MiB
inline constexpr std::size_t kMaxPayloadBytes = 256u << 20; // inflated
inline constexpr std::size_t kMaxRadii = 64;
inline constexpr std::size_t kMaxPatches = 1u << 20;
// Version 2 adds the tubes' start borders (Model::startBorders) after the
// borders; a model without any is written as version 1, byte for byte as
// before, and both versions are read.
inline constexpr int kFormatVersion = 2;

struct EncodeOptions {
    // The step coefficients are rounded to: the box diagonal / 2^bits.
    int bits = 12;
};
std::string encodeBinary(const Model& model, const EncodeOptions& options = {});
std::string encodeText(const Model& model);
// The step encodeBinary uses for `model` (each coefficient moves at most half of it).
double quantisationStep(const Model& model, const EncodeOptions& options = {});

struct ReadResult {
    std::optional<Model> model;
    std::string error; // "NAME: byte 12: ..." or "NAME:3:7: ..."
    bool ok() const { return model.has_value(); }
};
// Either form, told apart by the header.
ReadResult readModel(std::string_view bytes, std::string_view name);
ReadResult readModelFile(const std::string& path);
// Writing: the bytes of encodeBinary or encodeText, through
// mesh::writeFileReplacing (mesh/mesh_export.h).

} // namespace fl::pde
