// MainWindow: reload on change. The open file, its buffers and images are watched
// (SceneFileWatch); a change reloads the scene at once or offers to, as the setting
// (Settings › When the File Changes) says. A reload of the same file keeps the
// camera: a user with an exporter open beside the inspector looks at one spot.
#include "main_window.h"
#include "main_window_actions.h"

#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>

#include "log_dock.h"
#include "scene_file_watch.h"

namespace sherpa::editor {

void MainWindow::createReloadWatch(QMenu* settings_menu) {
    file_watch_ = new SceneFileWatch(this);
    connect(file_watch_, &SceneFileWatch::changed, this, &MainWindow::onSceneFilesChanged);
    connect(&context_, &EditorContext::sceneReady, this, [this] {
        const Scene* scene = context_.scene();
        file_watch_->watch(scene ? scene_files(context_.sceneSpec(), *scene) : QStringList());
    });
    reload_menu_ = settings_menu->addMenu(QString());
    reload_group_ = new QActionGroup(this);
    for (const bool automatic : {false, true}) {
        QAction* act = reload_group_->addAction(QString());
        act->setCheckable(true);
        act->setChecked(settings_.reloadAutomatically() == automatic);
        act->setData(automatic);
        connect(act, &QAction::triggered, this,
                [this, automatic] { setReloadAutomatically(automatic); });
        reload_menu_->addAction(act);
    }
}

void MainWindow::retranslateReload() {
    if (!reload_menu_) return;
    reload_menu_->setTitle(tr("When the File &Changes"));
    const QList<QAction*> acts = reload_group_->actions();
    acts[0]->setText(tr("&Offer to Reload"));
    acts[1]->setText(tr("&Reload Automatically"));
    for (QAction* act : acts)
        act->setStatusTip(tr("The open file, its buffers and its images are watched on disk"));
}

void MainWindow::setReloadAutomatically(bool automatic) {
    settings_.setReloadAutomatically(automatic);
    for (QAction* act : reload_group_->actions())
        act->setChecked(act->data().toBool() == automatic);
}

QStringList MainWindow::watchedFiles() const {
    return file_watch_ ? file_watch_->watched() : QStringList();
}

void MainWindow::onSceneFilesChanged(const QStringList& files) {
    if (!context_.scene() || files.isEmpty()) return;
    QStringList names;
    for (const QString& f : files) names << QFileInfo(f).fileName();
    const QString what = names.join(QStringLiteral(", "));
    if (settings_.reloadAutomatically()) {
        log_->append(LogDock::Level::Info, tr("%1 changed on disk: reloading.").arg(what));
        keep_camera_ = true;
        reloadScene();
        return;
    }
    log_->append(LogDock::Level::Info, tr("%1 changed on disk.").arg(what));
    if (reload_offer_) { // one offer at a time: it names what changed since
        reload_offer_->setText(tr("%1 changed on disk. Reload the scene?").arg(what));
        return;
    }
    auto* box = new QMessageBox(QMessageBox::Question, tr("File changed"),
                                tr("%1 changed on disk. Reload the scene?").arg(what),
                                QMessageBox::NoButton, this);
    box->setObjectName(QStringLiteral("reloadOffer"));
    QPushButton* reload = box->addButton(tr("&Reload"), QMessageBox::AcceptRole);
    box->addButton(tr("&Keep the Loaded Scene"), QMessageBox::RejectRole);
    box->setCheckBox(nullptr);
    box->setInformativeText(
        tr("Settings › When the File Changes › Reload Automatically reloads without asking."));
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::buttonClicked, this, [this, reload](QAbstractButton* b) {
        if (b != reload) return;
        keep_camera_ = true;
        reloadScene();
    });
    reload_offer_ = box;
    box->open(); // not modal: the scene stays usable while the user decides
}

} // namespace sherpa::editor
