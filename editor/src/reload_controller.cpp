// Reload on change (reload_controller.h): the watch follows the scene the context
// holds; each change is said in the log, then reloads or offers to (one offer at a
// time, naming what changed since).
#include "reload_controller.h"

#include <QActionGroup>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>

#include "editor_context.h"
#include "editor_settings.h"
#include "log_dock.h"
#include "scene_file_watch.h"

namespace sherpa::editor {

ReloadController::ReloadController(EditorContext& context, EditorSettings& settings, LogDock& log,
                                   QMenu& settings_menu, std::function<void()> reload,
                                   QWidget* window)
    : QObject(window), context_(context), settings_(settings), log_(log),
      reload_(std::move(reload)), window_(window), file_watch_(new SceneFileWatch(this)),
      menu_(settings_menu.addMenu(QString())), group_(new QActionGroup(this)) {
    connect(file_watch_, &SceneFileWatch::changed, this, &ReloadController::onFilesChanged);
    connect(&context_, &EditorContext::sceneReady, this, [this] {
        const scene::Scene* scene = context_.scene();
        file_watch_->watch(scene ? scene_files(context_.sceneSpec(), *scene) : QStringList());
    });
    for (const bool automatic : {false, true}) {
        QAction* act = group_->addAction(QString());
        act->setCheckable(true);
        act->setChecked(settings_.get(setting::kReloadAutomatically) == automatic);
        act->setData(automatic);
        connect(act, &QAction::triggered, this,
                [this, automatic] { setReloadAutomatically(automatic); });
        menu_->addAction(act);
    }
}

void ReloadController::retranslate() {
    menu_->setTitle(tr("When the File &Changes"));
    const QList<QAction*> acts = group_->actions();
    acts[0]->setText(tr("&Offer to Reload"));
    acts[1]->setText(tr("&Reload Automatically"));
    for (QAction* act : acts)
        act->setStatusTip(tr("The open file, its buffers and its images are watched on disk"));
}

void ReloadController::setReloadAutomatically(bool automatic) {
    settings_.set(setting::kReloadAutomatically, automatic);
    for (QAction* act : group_->actions()) act->setChecked(act->data().toBool() == automatic);
}

bool ReloadController::reloadAutomatically() const {
    return settings_.get(setting::kReloadAutomatically);
}

QStringList ReloadController::watchedFiles() const {
    return file_watch_->watched();
}

void ReloadController::onFilesChanged(const QStringList& files) {
    if (!context_.scene() || files.isEmpty()) return;
    QStringList names;
    for (const QString& f : files) names << QFileInfo(f).fileName();
    const QString what = names.join(QStringLiteral(", "));
    if (settings_.get(setting::kReloadAutomatically)) {
        log_.append(LogDock::Level::Info, tr("%1 changed on disk: reloading.").arg(what));
        reload_();
        return;
    }
    log_.append(LogDock::Level::Info, tr("%1 changed on disk.").arg(what));
    if (offer_) { // one offer at a time: it names what changed since
        offer_->setText(tr("%1 changed on disk. Reload the scene?").arg(what));
        return;
    }
    auto* box = new QMessageBox(QMessageBox::Question, tr("File changed"),
                                tr("%1 changed on disk. Reload the scene?").arg(what),
                                QMessageBox::NoButton, window_);
    box->setObjectName(QStringLiteral("reloadOffer"));
    QPushButton* reload = box->addButton(tr("&Reload"), QMessageBox::AcceptRole);
    box->addButton(tr("&Keep the Loaded Scene"), QMessageBox::RejectRole);
    box->setCheckBox(nullptr);
    box->setInformativeText(
        tr("Settings › When the File Changes › Reload Automatically reloads without asking."));
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::buttonClicked, this, [this, reload](QAbstractButton* b) {
        if (b == reload) reload_();
    });
    offer_ = box;
    box->open(); // not modal: the scene stays usable while the user decides
}

} // namespace sherpa::editor
