#include "texture_dock.h"

#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

#include "editor_context.h"
#include "format_values.h"
#include "scene_session.h"
#include "texture_table_model.h"
#include "view_fitting.h"

#include <sherpa/texture/texture_pipeline.h>

namespace sherpa::editor {

TextureDock::TextureDock(const EditorContext& context, QWidget* parent)
    : QDockWidget(parent), context_(context) {
    setObjectName(QStringLiteral("textureDock"));
    model_ = new TextureTableModel(this);
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    view_ = new QTableView(body);
    view_->setModel(model_);
    view_->verticalHeader()->hide();
    view_->setIconSize(QSize(kThumbnailSize / 2, kThumbnailSize / 2));
    view_->verticalHeader()->setDefaultSectionSize(kThumbnailSize / 2 + 4);
    view_->setSelectionBehavior(QAbstractItemView::SelectRows);
    view_->setSelectionMode(QAbstractItemView::SingleSelection);
    view_->setWordWrap(false);
    // What a user looks for first: whether it is there (State: "missing"), which
    // texture, what it is for and how big; the hashes and timings scroll in.
    show_columns_first(view_->horizontalHeader(),
                       {TextureTableModel::CacheStateColumn, TextureTableModel::NameColumn,
                        TextureTableModel::RoleColumn, TextureTableModel::SizeColumn,
                        TextureTableModel::FormatColumn});
    // Three rows: in one, the buttons need more than a side dock's width.
    auto* actions = new QGridLayout;
    totals_ = new QLabel(body);
    recompress_ = new QPushButton(body);
    clear_ = new QPushButton(body);
    open_folder_ = new QPushButton(body);
    // Enabled once the uploaded scene's textures came through a disk cache.
    recompress_->setEnabled(false);
    clear_->setEnabled(false);
    actions->addWidget(totals_, 0, 0, 1, 2);
    actions->addWidget(recompress_, 1, 0, 1, 2);
    actions->addWidget(clear_, 2, 0);
    actions->addWidget(open_folder_, 2, 1);
    layout->addWidget(view_);
    layout->addLayout(actions);
    setWidget(body);
    connect(open_folder_, &QPushButton::clicked, this, &TextureDock::openCacheFolderRequested);
    connect(clear_, &QPushButton::clicked, this, &TextureDock::clearCacheRequested);
    connect(recompress_, &QPushButton::clicked, this, [this] {
        if (context_.selection().current().texture >= 0)
            Q_EMIT recompressRequested(context_.selection().current().texture);
    });
    connect(view_->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) {
                if (current.isValid() && current.row() != context_.selection().current().texture)
                    Q_EMIT selectTextureRequested(current.row());
            });
    connect(&context_, &EditorContext::sceneReady, this, &TextureDock::showScene);
    connect(&context_.selection(), &SceneSelection::changed, this, &TextureDock::syncSelection);
    retranslate();
}

void TextureDock::retranslate() {
    setWindowTitle(tr("Texture Cache"));
    recompress_->setText(tr("Recompress selected"));
    clear_->setText(tr("Clear cache"));
    open_folder_->setText(tr("Open cache folder"));
    recompress_->setToolTip(
        tr("Delete the selected texture's cache files and load the scene again, which "
           "compresses it anew with the current quality"));
    clear_->setToolTip(tr("Delete every KTX2 file in the texture cache directory"));
    updateTotals();
}

void TextureDock::showScene() {
    const SharedSession& session = context_.sharedSession();
    model_->setSession(session);
    // The cache actions are enabled while the textures came through a disk cache.
    bool cached = false;
    if (session && session->textures)
        for (const tex::PreparedTexture& t : session->textures->textures)
            cached |= !t.cache_file.empty();
    recompress_->setEnabled(cached);
    clear_->setEnabled(cached);
    view_->resizeColumnsToContents();
    updateTotals();
}

void TextureDock::syncSelection() {
    const int t = context_.selection().current().texture;
    if (t >= 0 && t < model_->rowCount() && view_->currentIndex().row() != t) {
        view_->setCurrentIndex(model_->index(t, 0));
        view_->scrollTo(model_->index(t, 0));
    }
}

void TextureDock::setGpuBytes(std::int64_t bytes) {
    gpu_bytes_ = bytes;
    updateTotals();
}

void TextureDock::updateTotals() {
    const SceneSession* session = context_.session();
    const QString gpu =
        gpu_bytes_ < 0 ? tr("no renderer") : format::bytes(static_cast<std::uint64_t>(gpu_bytes_));
    totals_->setText(
        tr("%1 textures, %2 encoded on disk, %3 on the GPU, thumbnails decoded in %4 ms")
            .arg(model_->rowCount())
            .arg(format::bytes(model_->totalDiskBytes()))
            .arg(gpu)
            .arg(session ? session->timings.thumbnails_ms : 0.0, 0, 'f', 1));
}

} // namespace sherpa::editor
