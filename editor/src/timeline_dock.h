#pragma once
// The timeline (issue 16): animation selector, play/pause, scrub slider with the
// selected animation's key times as ticks, speed, loop, time readout, and the morph
// weight overrides. Context in (the scene); out: the Pose the viewport draws
// (pose(), poseChanged), evaluated on the GUI thread (evaluate_pose is microseconds).
#include <QDockWidget>
#include <QElapsedTimer>
#include <QSlider>
#include <QTimer>

#include <memory>
#include <optional>
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

class TimelineDock : public QDockWidget {
    Q_OBJECT
public:
    static constexpr int kSliderSteps = 10000;

    explicit TimelineDock(const EditorContext& context, QWidget* parent = nullptr);
    void retranslate();

    // The pose to draw now; null: the scene as loaded (no animation, no override).
    std::shared_ptr<const Pose> pose() const { return pose_; }
    // -1: none.
    int animation() const;
    void setAnimation(int animation);
    double time() const { return clock_.time; }
    const PlaybackClock& clock() const { return clock_; }
    void scrubTo(double seconds);
    void setPlaying(bool playing);
    void setSpeed(double speed);
    void setLoop(bool loop);
    // One step of the play loop, as the timer does with the elapsed wall clock.
    void advance(double seconds);

    QComboBox* animationBox() const { return animations_; }
    TimelineSlider* slider() const { return slider_; }
    QLabel* timeLabel() const { return time_label_; }
    MorphWeightsPanel* morphWeights() const { return morph_; }

Q_SIGNALS:
    void poseChanged();

private:
    void onSceneChanged();
    void onTick();
    void refresh(); // pose (when its inputs changed), slider, readout
    void updatePlayButton();
    // An animation with a non-empty key range: what play and the slider act on.
    bool playable() const;

    const EditorContext& context_;
    PlaybackClock clock_;
    std::shared_ptr<const Pose> pose_;
    // What pose_ was made from. Retranslating, play/pause or a tick that lands on the same
    // time make no new pose: a new one would have the viewport rewrite and redraw it.
    struct PoseInputs {
        int animation = -1;
        double time = 0.0;
        MorphOverrides overrides;
        bool operator==(const PoseInputs&) const = default;
    };
    std::optional<PoseInputs> pose_inputs_; // none: make it (another scene)
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
