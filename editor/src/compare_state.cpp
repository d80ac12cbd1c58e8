#include "compare_state.h"

#include "view_catalog.h"

namespace sherpa::editor {

void CompareState::setMode(ViewportMode mode) {
    comparison_.mode = mode;
    Q_EMIT changed();
}

void CompareState::setSide(SideB side, std::uint32_t view) {
    comparison_.side = side;
    comparison_.view = view;
    Q_EMIT changed();
}

void CompareState::chooseSide(SideB side, std::uint32_t view) {
    // Choosing what to compare with means comparing: from Raster or Ray traced the
    // viewport goes to Split (as it does when another file is loaded as side B).
    if (!comparison_.comparing()) comparison_.mode = ViewportMode::Split;
    setSide(side, view);
}

void CompareState::setDivider(float fraction) {
    comparison_.divider = fraction;
    Q_EMIT changed();
}

void CompareState::setHeatScale(float heat_max) {
    comparison_.heat_max = heat_max;
    Q_EMIT changed();
}

void CompareState::setThreshold(float threshold) {
    comparison_.threshold = threshold;
    Q_EMIT changed();
}

void CompareState::setRayTracing(bool available) {
    offer_.ray_tracing = available;
    // Without rays, a comparison starts against the normal view.
    if (!available && comparison_.side == SideB::RayTraced) {
        comparison_.side = SideB::OtherView;
        if (const auto normal = ViewCatalog::viewId(QStringLiteral("normal")))
            comparison_.view = *normal;
    }
    Q_EMIT offerChanged();
}

void CompareState::setOtherFile(const QString& name, std::optional<scene::TangentMethod> tangents) {
    offer_.file = name;
    offer_.tangents = name.isEmpty() ? std::nullopt : tangents;
    Q_EMIT offerChanged();
}

} // namespace sherpa::editor
