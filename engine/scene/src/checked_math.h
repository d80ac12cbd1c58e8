#pragma once
// Internal: size arithmetic on numbers read from a file. A glTF file states offsets,
// strides and counts up to 2^64; every sum or product of them that indexes memory
// goes through these, so a wrapped result can never pass a range check.
#include <cstddef>
#include <optional>

namespace sherpa::scene::detail {

// a + b, or nullopt when it does not fit in std::size_t.
constexpr std::optional<std::size_t> checked_add(std::size_t a, std::size_t b) {
    std::size_t r = 0;
    if (__builtin_add_overflow(a, b, &r)) return std::nullopt;
    return r;
}

// a * b, or nullopt when it does not fit in std::size_t.
constexpr std::optional<std::size_t> checked_mul(std::size_t a, std::size_t b) {
    std::size_t r = 0;
    if (__builtin_mul_overflow(a, b, &r)) return std::nullopt;
    return r;
}

// True when [offset, offset + length) lies inside [0, size), without overflow.
constexpr bool range_fits(std::size_t offset, std::size_t length, std::size_t size) {
    return offset <= size && length <= size - offset;
}

} // namespace sherpa::scene::detail
