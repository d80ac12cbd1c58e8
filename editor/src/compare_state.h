#pragma once
// What the viewport's A/B comparison is, apart from the menus that change it: the mode
// and side B (ViewportComparison, which CompareController puts into every frame), and
// what side B can be (the ray tracer where the device has it; the other file loaded).
// changed(): what is drawn changed. offerChanged(): only what the menus offer did.
#include <QObject>
#include <QString>

#include <optional>

#include <sherpa/scene/tangents.h>

#include "viewport_mode.h"

namespace sherpa::editor {

// What side B can show besides another debug view.
struct SideBOffer {
    bool ray_tracing = true; // the device ray traces
    QString file;            // the other file's name in the menu; empty: none loaded
    // It is this file with every primitive's tangents made by that method.
    std::optional<scene::TangentMethod> tangents;
};

class CompareState : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;

    const ViewportComparison& comparison() const { return comparison_; }
    const SideBOffer& offer() const { return offer_; }

    void setMode(ViewportMode mode);
    void setSide(SideB side, std::uint32_t view = 0);
    // The side chosen in a menu: a comparison starts (Split) if none is shown.
    void chooseSide(SideB side, std::uint32_t view = 0);
    void setDivider(float fraction);
    // Difference: full heat at this difference (0: automatic), "over" above threshold.
    void setHeatScale(float heat_max);
    void setThreshold(float threshold);
    // Without rays, side B falls back from the ray tracer to the normal view.
    void setRayTracing(bool available);
    // Empty `name`: no other file (and no tangents).
    void setOtherFile(const QString& name,
                      std::optional<scene::TangentMethod> tangents = std::nullopt);

Q_SIGNALS:
    void changed();
    void offerChanged();

private:
    ViewportComparison comparison_;
    SideBOffer offer_;
};

} // namespace sherpa::editor
