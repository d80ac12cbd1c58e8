#pragma once
// Dock 4: every texture with thumbnail, source, role and sizes, totals, and the
// cache actions. Cache-only columns and actions stay disabled until the texture
// cache (engine/texture) is part of the build.
#include <QDockWidget>

#include "scene_session.h"

class QLabel;
class QPushButton;
class QTableView;

namespace sherpa::editor {

class EditorContext;
class TextureTableModel;

class TextureDock : public QDockWidget {
    Q_OBJECT
public:
    explicit TextureDock(const EditorContext& context, QWidget* parent = nullptr);
    void retranslate();
    TextureTableModel* model() const { return model_; }
    QTableView* view() const { return view_; }
    // Bytes the renderer holds for the scene's textures (-1: no renderer), for the totals.
    void setGpuBytes(std::int64_t bytes);
    QPushButton* recompressButton() const { return recompress_; }
    QPushButton* clearCacheButton() const { return clear_; }

Q_SIGNALS:
    void selectTextureRequested(int texture);
    void openCacheFolderRequested();
    void recompressRequested(int texture); // drop its cache files and prepare it again
    void clearCacheRequested();

private:
    void showScene();
    void syncSelection();
    void updateTotals();

    const EditorContext& context_;
    TextureTableModel* model_;
    QTableView* view_;
    QLabel* totals_;
    QPushButton* recompress_;
    QPushButton* clear_;
    QPushButton* open_folder_;
    std::int64_t gpu_bytes_ = -1;
};

} // namespace sherpa::editor
