#pragma once
// The timeline (issue 16): animation selector, play/pause, scrub slider with the
// selected animation's key times as ticks, speed, loop, time readout, and the morph
// weight overrides. Context in (the scene); out: the Pose the viewport draws
// (playback().pose(), poseChanged), evaluated on the GUI thread (evaluate_pose is
// microseconds).
#include <QDockWidget>
#include <QElapsedTimer>
#include <QSlider>
#include <QTimer>

#include <vector>

#include "motion_playback.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QToolButton;

namespace sherpa::editor {

class EditorContext;
class MorphWeightsPanel;

// A horizontal slider that draws a tick under the groove at each key time.
class TimelineSlider : public QSlider {
    Q_OBJECT
public:
    explicit TimelineSlider(QWidget* parent = nullptr);
    // Key positions as fractions of the range [0, 1].
    void setTicks(std::vector<double> fractions);
    const std::vector<double>& ticks() const { return ticks_; }

protected:
    void paintEvent(QPaintEvent* e) override;

private:
    std::vector<double> ticks_;
};

// The widgets over a Playback: they show it and act on it. The tests find the
// widgets as children (findChild), the way the window's suites do.
class TimelineDock : public QDockWidget {
    Q_OBJECT
public:
    static constexpr int kSliderSteps = 10000;

    explicit TimelineDock(const EditorContext& context, QWidget* parent = nullptr);
    void retranslate();

    // The animation, its clock and the pose to draw (null: the scene as loaded).
    const Playback& playback() const { return playback_; }
    // -1: none.
    void setAnimation(int animation);
    void scrubTo(double seconds);
    void setPlaying(bool playing);
    void setSpeed(double speed);
    void setLoop(bool loop);
    // One step of the play loop, as the timer does with the elapsed wall clock.
    void advance(double seconds);

Q_SIGNALS:
    void poseChanged();

private:
    void onSceneChanged();
    void onAnimationSelected(); // the box's choice into the playback, slider and button
    void onTick();
    void refresh(); // pose (when its inputs changed), slider, readout
    void updatePlayButton();

    const EditorContext& context_;
    Playback playback_;
    QTimer timer_;
    QElapsedTimer elapsed_;
    QComboBox* animations_;
    QToolButton* play_;
    TimelineSlider* slider_;
    QLabel* time_label_;
    QLabel* speed_label_;
    QDoubleSpinBox* speed_;
    QCheckBox* loop_;
    MorphWeightsPanel* morph_;
    QWidget* morph_area_; // hidden for scenes without morph targets
};

} // namespace sherpa::editor
