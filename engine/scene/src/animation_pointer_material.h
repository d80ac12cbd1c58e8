#pragma once
// KHR_animation_pointer's material targets (private to the scene layer): the Object
// Model's material pointers, core and ratified extensions, resolved against a material
// and their values written into it. animation_pointer.cpp does lights, cameras and nodes.
#include <sherpa/scene/animation_pointer.h>

#include <string>
#include <string_view>

namespace sherpa::scene {

// Why `rest` (the pointer after "/materials/M/") cannot be animated on `m` (empty: it
// can, `out.property` and `out.slot` set).
std::string resolve_material_pointer(const MaterialInstance& m, std::uint32_t index,
                                     std::string_view rest, AnimatedTarget& out);

// The pointer after "/materials/M/" of a material target ("" for other targets).
std::string material_pointer_path(const AnimatedTarget& target);

// Writes one material value into `m`; false when `p` is not a material property.
bool apply_material_property(const AnimatedProperty& p, MaterialInstance& m);

} // namespace sherpa::scene
