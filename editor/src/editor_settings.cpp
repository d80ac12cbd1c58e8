#include "editor_settings.h"

#include <sherpa/texture/texture_cache.h>

namespace sherpa::editor {

QString default_cache_directory() {
    return QString::fromStdString(sherpa::tex::default_cache_dir_from_environment().string());
}

void EditorSettings::addRecentFile(const QString& spec) {
    if (spec.startsWith(QLatin1String("builtin:"))) return;
    QStringList list = get(setting::kRecentFiles);
    list.removeAll(spec);
    list.prepend(spec);
    while (list.size() > kMaxRecent) list.removeLast();
    set(setting::kRecentFiles, list);
}

} // namespace sherpa::editor
