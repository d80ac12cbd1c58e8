#pragma once
// Internal: the glTF 2.0 core schema as data, one entry per object kind (what
// validate_schema.cpp walks): each property's type, whether it is required, its range,
// enumeration or reference target.
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string_view>

namespace sherpa::scene::detail::schema {

enum class T : std::uint8_t {
    Index,      // integer >= 0 that must resolve into root array `target`
    IndexArray, // array of such
    Int,        // integer in [lo, hi]
    Num,        // number in [lo, hi] (exclusive low when `open`)
    NumArray,   // numbers in [lo, hi]; length in `lengths` when given
    Str,
    Bool,
    Obj,    // checked with kind `target`
    ObjArr, // array of objects of kind `target`
    IntEnum,
    StrEnum,
    Any,
};

struct Prop {
    std::string_view name; // with its length: compared with each key of a checked object
    T type;
    bool required = false;
    const char* target = nullptr; // Index*: root array; Obj*: kind
    double lo = -INFINITY, hi = INFINITY;
    bool open = false;                    // Num: lo is exclusive
    std::initializer_list<int> lengths{}; // NumArray lengths; IntEnum values
    std::initializer_list<const char*> words{};
    bool zero_ok = false; // Num: 0 is allowed outside [lo, hi] (KHR_materials_ior's ior)
};

struct Kind {
    const char* name;
    std::initializer_list<Prop> props;
    // A material extension the Khronos validator does not know: its problems carry
    // SHERPA_ codes (SHERPA_VALUE_NOT_IN_RANGE, ...), since it reports none for them.
    bool sherpa_codes = false;
};

// The kind called `name` ("root", "accessor", ...); null when the table has none.
const Kind* kind_named(const char* name);
// The schema of material extension `name` (its object, under material.extensions),
// or null when Sherpa has none.
const Kind* material_extension_kind(std::string_view name);

} // namespace sherpa::scene::detail::schema
