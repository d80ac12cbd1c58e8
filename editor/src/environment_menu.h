#pragma once
// The Environment menu (none, the built-in room, Blender's studio lights when installed,
// a file; background, rotation, intensity, the default sun, energy compensation) and
// View › Tone Mapping (the curve and the exposure). Actions in, plain state out: the
// environment choice (the window gives it to the viewport when it changes) and the
// ViewportDisplay the window puts into every frame.
#include <QObject>
#include <QString>
#include <QStringList>

#include <vector>

#include "gpu_viewport.h" // ViewportDisplay

class QAction;
class QActionGroup;
class QMenu;
class QWidget;

namespace sherpa::editor {

class EnvironmentMenu : public QObject {
    Q_OBJECT
public:
    explicit EnvironmentMenu(QWidget* parent);
    QMenu* environmentMenu() const { return environment_; }
    QMenu* toneMenu() const { return tone_; } // for the View menu
    const render::EnvironmentChoice& choice() const { return choice_; }
    const ViewportDisplay& display() const { return display_; }

    // The command line's settings (sherpa --environment, --tone-map ...).
    void setChoice(const render::EnvironmentChoice& choice);
    void setDisplay(const ViewportDisplay& display);
    void retranslate();

Q_SIGNALS:
    void environmentChanged(); // choice() changed: the viewport remakes the maps
    void displayChanged();     // display() changed: the next frame shows it

private:
    void sync();
    QWidget* parent_;
    render::EnvironmentChoice choice_;
    ViewportDisplay display_;
    QMenu *environment_, *background_, *tone_;
    QActionGroup *source_group_, *background_group_, *tone_group_;
    QAction *none_, *room_, *open_, *rotate_left_, *rotate_right_, *brighter_, *darker_,
        *reset_intensity_, *sun_, *compensation_;
    std::vector<QAction*> studio_; // one per installed studio light
    QAction *bg_environment_, *bg_blurred_, *bg_color_;
    std::vector<QAction*> tone_actions_; // render::ToneMap order
    QAction *exposure_up_, *exposure_down_, *exposure_reset_;
};

} // namespace sherpa::editor
