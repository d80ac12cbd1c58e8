#pragma once
// What the families that render share: their device, and the report of one that
// cannot ray trace (the shadows and lighting families' references are rays).
#include <string>

#include <sherpa/gpu/context.h>
#include <sherpa/lab/family.h>

#include "lab_support.h"

namespace sherpa::lab::detail {

inline gpu::ContextOptions family_context(bool validation, bool ray_tracing) {
    gpu::ContextOptions co;
    co.validation = validation;
    co.ray_tracing = ray_tracing;
    return co;
}

// False, with every method's note saying why and progress finished, when `context`
// does not ray trace: `missing` is what the family then lacks ("no reference ...").
inline bool ray_traces(const gpu::Context& context, FamilyReport& report, Progress& progress,
                       const std::string& missing) {
    if (context.info().ray_tracing_enabled) return true;
    for (MethodResult& r : report.methods)
        r.note = "device '" + context.info().name + "' does not ray trace: " + missing;
    progress.finish();
    return false;
}

} // namespace sherpa::lab::detail
