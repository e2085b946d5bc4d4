#pragma once
// Names of the command-line choices (kernels, precisions, structures): one table per enum,
// read both ways, so a name and its value cannot drift apart.
#include <array>
#include <optional>
#include <string_view>
#include <utility>

namespace raystep {

template <typename E, std::size_t N>
using NameTable = std::array<std::pair<E, std::string_view>, N>;

template <typename E, std::size_t N>
constexpr std::optional<E> valueNamed(const NameTable<E, N>& table, std::string_view name) {
    for (const auto& [value, n] : table)
        if (n == name) return value;
    return std::nullopt;
}

template <typename E, std::size_t N>
constexpr std::string_view nameOf(const NameTable<E, N>& table, E value) {
    for (const auto& [v, n] : table)
        if (v == value) return n;
    return "?";
}

}  // namespace raystep
