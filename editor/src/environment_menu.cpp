#include "environment_menu.h"

#include <QAction>
#include <QActionGroup>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QWidget>

#include <algorithm>
#include <cmath>

namespace sherpa::editor {

EnvironmentMenu::EnvironmentMenu(QWidget* parent) : QObject(parent), parent_(parent) {
    environment_ = new QMenu(parent);
    source_group_ = new QActionGroup(this);
    auto checkable = [&](QMenu* menu, QActionGroup* group) {
        QAction* a = menu->addAction(QString());
        a->setCheckable(true);
        if (group) group->addAction(a);
        return a;
    };
    none_ = checkable(environment_, source_group_);
    room_ = checkable(environment_, source_group_);
    connect(none_, &QAction::triggered, this, [this] {
        choice_ = {render::EnvironmentChoice::Kind::None, {}};
        Q_EMIT environmentChanged();
    });
    connect(room_, &QAction::triggered, this, [this] {
        choice_ = {render::EnvironmentChoice::Kind::Room, {}};
        Q_EMIT environmentChanged();
    });
    const auto lights = render::installed_studio_lights();
    if (!lights.empty()) environment_->addSeparator();
    for (const std::string& file : lights) {
        QAction* a = checkable(environment_, source_group_);
        a->setData(QString::fromStdString(file));
        a->setText(QFileInfo(QString::fromStdString(file)).completeBaseName());
        connect(a, &QAction::triggered, this, [this, file] {
            choice_ = {render::EnvironmentChoice::Kind::File, file};
            Q_EMIT environmentChanged();
        });
        studio_.push_back(a);
    }
    environment_->addSeparator();
    open_ = environment_->addAction(QString());
    connect(open_, &QAction::triggered, this, [this] {
        const QString file =
            QFileDialog::getOpenFileName(parent_, tr("Open Environment"), QString(),
                                         tr("HDR images (*.hdr *.exr);;All files (*)"));
        if (file.isEmpty()) {
            sync();
            return;
        }
        choice_ = {render::EnvironmentChoice::Kind::File, file.toStdString()};
        sync();
        Q_EMIT environmentChanged();
    });
    environment_->addSeparator();
    background_ = environment_->addMenu(QString());
    background_group_ = new QActionGroup(this);
    bg_environment_ = checkable(background_, background_group_);
    bg_blurred_ = checkable(background_, background_group_);
    bg_color_ = checkable(background_, background_group_);
    const std::pair<QAction*, render::Background> backgrounds[] = {
        {bg_environment_, render::Background::Environment},
        {bg_blurred_, render::Background::Blurred},
        {bg_color_, render::Background::Color}};
    for (const auto& [action, b] : backgrounds)
        connect(action, &QAction::triggered, this, [this, b = b] {
            display_.background = b;
            Q_EMIT displayChanged();
        });
    rotate_left_ = environment_->addAction(QString());
    rotate_right_ = environment_->addAction(QString());
    brighter_ = environment_->addAction(QString());
    darker_ = environment_->addAction(QString());
    reset_intensity_ = environment_->addAction(QString());
    auto adjust = [this](QAction* a, auto change) {
        connect(a, &QAction::triggered, this, [this, change] {
            change(display_);
            Q_EMIT displayChanged();
        });
    };
    adjust(rotate_left_, [](ViewportDisplay& d) {
        d.environmentRotation = std::fmod(d.environmentRotation + 345.0f, 360.0f);
    });
    adjust(rotate_right_, [](ViewportDisplay& d) {
        d.environmentRotation = std::fmod(d.environmentRotation + 15.0f, 360.0f);
    });
    adjust(brighter_, [](ViewportDisplay& d) { d.environmentIntensity *= 1.4142135f; });
    adjust(darker_, [](ViewportDisplay& d) { d.environmentIntensity /= 1.4142135f; });
    adjust(reset_intensity_, [](ViewportDisplay& d) {
        d.environmentIntensity = 1.0f;
        d.environmentRotation = 0.0f;
    });
    environment_->addSeparator();
    sun_ = checkable(environment_, nullptr);
    compensation_ = checkable(environment_, nullptr);
    connect(sun_, &QAction::toggled, this, [this](bool on) {
        if (display_.sun == on) return;
        display_.sun = on;
        Q_EMIT displayChanged();
    });
    connect(compensation_, &QAction::toggled, this, [this](bool on) {
        if (display_.energyCompensation == on) return;
        display_.energyCompensation = on;
        Q_EMIT displayChanged();
    });

    tone_ = new QMenu(parent);
    tone_group_ = new QActionGroup(this);
    for (const std::string_view name : render::tone_map_names()) {
        QAction* a = checkable(tone_, tone_group_);
        const render::ToneMap t = *render::parse_tone_map(name);
        connect(a, &QAction::triggered, this, [this, t] {
            display_.toneMap = t;
            Q_EMIT displayChanged();
        });
        tone_actions_.push_back(a);
    }
    tone_->addSeparator();
    exposure_up_ = tone_->addAction(QString());
    exposure_down_ = tone_->addAction(QString());
    exposure_reset_ = tone_->addAction(QString());
    adjust(exposure_up_, [](ViewportDisplay& d) { d.exposure += 0.5f; });
    adjust(exposure_down_, [](ViewportDisplay& d) { d.exposure -= 0.5f; });
    adjust(exposure_reset_, [](ViewportDisplay& d) { d.exposure = 0.0f; });
    connect(this, &EnvironmentMenu::displayChanged, this, &EnvironmentMenu::retranslate);
    connect(this, &EnvironmentMenu::environmentChanged, this, &EnvironmentMenu::sync);
    retranslate();
}

void EnvironmentMenu::setChoice(const render::EnvironmentChoice& choice) {
    choice_ = choice;
    sync();
    Q_EMIT environmentChanged();
}

void EnvironmentMenu::setDisplay(const ViewportDisplay& display) {
    display_ = display;
    retranslate();
    Q_EMIT displayChanged();
}

void EnvironmentMenu::sync() {
    using Kind = render::EnvironmentChoice::Kind;
    none_->setChecked(choice_.kind == Kind::None);
    room_->setChecked(choice_.kind == Kind::Room);
    bool listed = false;
    for (QAction* a : studio_) {
        const bool on =
            choice_.kind == Kind::File && a->data().toString().toStdString() == choice_.path;
        a->setChecked(on);
        listed |= on;
    }
    open_->setCheckable(choice_.kind == Kind::File && !listed);
    open_->setChecked(choice_.kind == Kind::File && !listed);
    const bool lit = choice_.kind != Kind::None;
    background_->setEnabled(lit);
    for (QAction* a :
         {rotate_left_, rotate_right_, brighter_, darker_, reset_intensity_, compensation_})
        a->setEnabled(lit);
    bg_environment_->setChecked(display_.background == render::Background::Environment);
    bg_blurred_->setChecked(display_.background == render::Background::Blurred);
    bg_color_->setChecked(display_.background == render::Background::Color);
    sun_->setChecked(display_.sun);
    compensation_->setChecked(display_.energyCompensation);
    for (std::size_t i = 0; i < tone_actions_.size(); ++i)
        tone_actions_[i]->setChecked(static_cast<std::size_t>(display_.toneMap) == i);
}

void EnvironmentMenu::retranslate() {
    environment_->setTitle(tr("&Environment"));
    none_->setText(tr("&None (Ambient Only)"));
    room_->setText(tr("&Room (Built In)"));
    const bool other = choice_.kind == render::EnvironmentChoice::Kind::File &&
                       std::none_of(studio_.begin(), studio_.end(), [&](QAction* a) {
                           return a->data().toString().toStdString() == choice_.path;
                       });
    open_->setText(other ? tr("&Open HDR or EXR… (%1)")
                               .arg(QFileInfo(QString::fromStdString(choice_.path)).fileName())
                         : tr("&Open HDR or EXR…"));
    background_->setTitle(tr("&Background"));
    bg_environment_->setText(tr("&Environment"));
    bg_blurred_->setText(tr("&Blurred"));
    bg_color_->setText(tr("&Solid Colour"));
    rotate_left_->setText(
        tr("Rotate −15° (now %1°)").arg(double(display_.environmentRotation), 0, 'f', 0));
    rotate_right_->setText(
        tr("Rotate +15° (now %1°)").arg(double(display_.environmentRotation), 0, 'f', 0));
    brighter_->setText(
        tr("Brighter (intensity %1)").arg(double(display_.environmentIntensity), 0, 'f', 2));
    darker_->setText(tr("Darker"));
    reset_intensity_->setText(tr("Reset Rotation and Intensity"));
    sun_->setText(tr("Default &Sun"));
    compensation_->setText(tr("Energy &Compensation (Multiple Scattering)"));
    tone_->setTitle(tr("&Tone Mapping"));
    const QString tone_names[] = {tr("Khronos PBR &Neutral"), tr("&ACES Filmic"), tr("A&gX"),
                                  tr("&Linear (Clamp)")};
    for (std::size_t i = 0; i < tone_actions_.size(); ++i) tone_actions_[i]->setText(tone_names[i]);
    exposure_up_->setText(
        tr("Exposure +½ Stop (now %1 EV)").arg(double(display_.exposure), 0, 'f', 1));
    exposure_down_->setText(tr("Exposure −½ Stop"));
    exposure_reset_->setText(tr("Exposure 0 EV"));
    sync();
}

} // namespace sherpa::editor
