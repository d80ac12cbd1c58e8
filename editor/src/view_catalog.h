#pragma once
// The debug views and overlays the renderer offers, by the names its
// RenderSettings parser accepts (--view NAME, settings), with display labels.
#include <QCoreApplication>
#include <QString>

#include <vector>

namespace sherpa::editor {

struct ViewEntry {
    const char* name; // renderer's name, stable (settings, command line)
    QString label;    // translated
};

class ViewCatalog {
    Q_DECLARE_TR_FUNCTIONS(ViewCatalog)
public:
    static std::vector<ViewEntry> views();
    static std::vector<ViewEntry> overlays();
    static bool isView(const QString& name);
};

} // namespace sherpa::editor
