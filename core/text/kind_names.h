#pragma once
// A kind (an enum) and the word a file, a manifest or a message writes for
// it: one table per kind, read once at the edge in both directions. The one
// form of enum-to-name table in the program.
#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>

namespace fl::text {

template <class Kind, std::size_t N>
using KindNames = std::array<std::pair<std::string_view, Kind>, N>;

template <class Kind, std::size_t N>
constexpr std::optional<Kind> kindNamed(const KindNames<Kind, N>& table, std::string_view word) {
    for (const auto& [name, kind] : table)
        if (name == word) return kind;
    return std::nullopt;
}

template <class Kind, std::size_t N>
constexpr std::string_view nameOfKind(const KindNames<Kind, N>& table, Kind kind) {
    for (const auto& [name, k] : table)
        if (k == kind) return name;
    return "?";
}

} // namespace fl::text
