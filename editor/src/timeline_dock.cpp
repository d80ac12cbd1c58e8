#include "timeline_dock.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QStyleOptionSlider>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

#include "editor_context.h"
#include "morph_weights_panel.h"

namespace sherpa::editor {

namespace {
constexpr int kTickMs = 16; // the play loop's timer; frames are asked for at this rate
} // namespace

TimelineSlider::TimelineSlider(QWidget* parent) : QSlider(Qt::Horizontal, parent) {
    setRange(0, TimelineDock::kSliderSteps);
    setMinimumHeight(28); // room under the groove for the key ticks
}

void TimelineSlider::setTicks(std::vector<double> fractions) {
    ticks_ = std::move(fractions);
    update();
}

void TimelineSlider::paintEvent(QPaintEvent* e) {
    QSlider::paintEvent(e);
    if (ticks_.empty()) return;
    QStyleOptionSlider opt;
    initStyleOption(&opt);
    const QRect groove =
        style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderGroove, this);
    const QRect handle =
        style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderHandle, this);
    // The handle's centre travels over the groove less the handle's length.
    const int span = groove.width() - handle.width();
    QPainter p(this);
    p.setPen(QPen(palette().color(QPalette::Highlight), 1));
    const int y = std::min(height() - 2, groove.bottom() + 3);
    for (const double f : ticks_) {
        const int x = groove.left() + handle.width() / 2 +
                      static_cast<int>(std::lround(f * static_cast<double>(span)));
        p.drawLine(x, y, x, y + 5);
    }
}

TimelineDock::TimelineDock(const EditorContext& context, QWidget* parent)
    : QDockWidget(parent), context_(context) {
    setObjectName(QStringLiteral("timelineDock"));
    auto* body = new QWidget(this);
    auto* outer = new QHBoxLayout(body);
    outer->setContentsMargins(4, 2, 4, 2);

    auto* controls = new QVBoxLayout;
    auto* top = new QHBoxLayout;
    animations_ = new QComboBox(body);
    animations_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    play_ = new QToolButton(body);
    play_->setCheckable(true);
    slider_ = new TimelineSlider(body);
    time_label_ = new QLabel(body);
    time_label_->setObjectName(QStringLiteral("timelineTime"));
    time_label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    top->addWidget(animations_);
    top->addWidget(play_);
    top->addWidget(slider_, 1);
    top->addWidget(time_label_);
    auto* bottom = new QHBoxLayout;
    speed_label_ = new QLabel(body);
    speed_ = new QDoubleSpinBox(body);
    speed_->setRange(0.05, 8.0);
    speed_->setSingleStep(0.25);
    speed_->setDecimals(2);
    speed_->setValue(1.0);
    speed_->setSuffix(QStringLiteral("×"));
    loop_ = new QCheckBox(body);
    loop_->setChecked(true);
    bottom->addWidget(speed_label_);
    bottom->addWidget(speed_);
    bottom->addWidget(loop_);
    bottom->addStretch(1);
    controls->addLayout(top);
    controls->addLayout(bottom);
    controls->addStretch(1);

    morph_ = new MorphWeightsPanel;
    auto* scroll = new QScrollArea(body);
    scroll->setWidget(morph_);
    scroll->setWidgetResizable(true);
    scroll->setMinimumWidth(260);
    scroll->setMinimumHeight(120); // two targets without scrolling
    morph_area_ = scroll;
    outer->addLayout(controls, 3);
    outer->addWidget(scroll, 1);
    setWidget(body);

    timer_.setInterval(kTickMs);
    connect(&timer_, &QTimer::timeout, this, &TimelineDock::onTick);
    connect(animations_, &QComboBox::currentIndexChanged, this, &TimelineDock::onAnimationSelected);
    connect(play_, &QToolButton::toggled, this, &TimelineDock::setPlaying);
    connect(slider_, &QSlider::valueChanged, this, [this](int v) {
        const PlaybackClock& clock = playback_.clock();
        scrubTo(clock.start + clock.duration() * v / kSliderSteps);
    });
    connect(speed_, &QDoubleSpinBox::valueChanged, this, &TimelineDock::setSpeed);
    connect(loop_, &QCheckBox::toggled, this, &TimelineDock::setLoop);
    connect(morph_, &MorphWeightsPanel::overridesChanged, this, &TimelineDock::refresh);
    connect(&context_, &EditorContext::sceneReady, this, &TimelineDock::onSceneChanged);
    retranslate();
    onSceneChanged();
}

void TimelineDock::retranslate() {
    setWindowTitle(tr("Timeline"));
    speed_label_->setText(tr("Speed"));
    loop_->setText(tr("Loop"));
    slider_->setToolTip(tr("Scrub; the ticks are the animation's key times"));
    if (animations_->count() > 0) animations_->setItemText(0, tr("No animation"));
    updatePlayButton();
    morph_->retranslate();
    refresh();
}

void TimelineDock::setAnimation(int animation) {
    animations_->setCurrentIndex(animation + 1); // item 0: none
}

void TimelineDock::onAnimationSelected() {
    playback_.selectAnimation(animations_->currentIndex() - 1);
    slider_->setTicks(playback_.keyFractions());
    timer_.stop();
    updatePlayButton();
    refresh();
}

void TimelineDock::onSceneChanged() {
    const scene::Scene* scene = context_.scene();
    playback_.setScene(context_.sharedScene());
    // The first animation, paused at its start: what the file shows first.
    const int first = scene && !scene->animations.empty() ? 0 : -1;
    {
        const QSignalBlocker block(animations_);
        animations_->clear();
        animations_->addItem(tr("No animation"));
        if (scene)
            for (std::size_t a = 0; a < scene->animations.size(); ++a) {
                const QString name = QString::fromStdString(scene->animations[a].name);
                animations_->addItem(name.isEmpty() ? tr("Animation %1").arg(a)
                                                    : tr("%1: %2").arg(a).arg(name));
            }
        animations_->setEnabled(scene && !scene->animations.empty());
        animations_->setCurrentIndex(first + 1);
    }
    morph_->setScene(scene);
    morph_area_->setVisible(!morph_->empty());
    onAnimationSelected();
}

void TimelineDock::scrubTo(double seconds) {
    playback_.clock().scrub(seconds);
    refresh();
}

void TimelineDock::setPlaying(bool playing) {
    playback_.clock().play(playing && playback_.playable());
    if (playback_.clock().playing) {
        elapsed_.start();
        timer_.start();
    } else {
        timer_.stop();
    }
    updatePlayButton();
    refresh();
}

void TimelineDock::setSpeed(double speed) {
    playback_.clock().speed = speed;
    if (std::abs(speed_->value() - speed) > 1e-9) speed_->setValue(speed);
}

void TimelineDock::setLoop(bool loop) {
    playback_.clock().loop = loop;
    if (loop_->isChecked() != loop) loop_->setChecked(loop);
}

void TimelineDock::onTick() {
    const double seconds = static_cast<double>(elapsed_.nsecsElapsed()) / 1e9;
    elapsed_.restart();
    advance(seconds);
}

void TimelineDock::advance(double seconds) {
    PlaybackClock& clock = playback_.clock();
    const bool was_playing = clock.playing;
    if (clock.advance(seconds)) refresh();
    if (was_playing && !clock.playing) { // a non-looping run reached its end
        timer_.stop();
        updatePlayButton();
    }
}

void TimelineDock::updatePlayButton() {
    const QSignalBlocker block(play_);
    const bool playing = playback_.clock().playing;
    play_->setChecked(playing);
    play_->setEnabled(playback_.playable());
    play_->setText(playing ? tr("Pause") : tr("Play"));
    play_->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    play_->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
}

void TimelineDock::refresh() {
    const bool changed = playback_.updatePose(morph_->overrides());
    if (changed) morph_->showPose(playback_.pose().get());
    const PlaybackClock& clock = playback_.clock();
    {
        const QSignalBlocker block(slider_);
        slider_->setValue(static_cast<int>(std::lround(clock.fraction() * kSliderSteps)));
        slider_->setEnabled(playback_.playable());
    }
    time_label_->setText(
        playback_.animation() < 0
            ? tr("no animation")
            : tr("%1 / %2 s").arg(clock.time, 0, 'f', 3).arg(clock.end, 0, 'f', 3));
    if (changed) Q_EMIT poseChanged();
}

} // namespace sherpa::editor
