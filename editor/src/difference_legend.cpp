// The engine's header first: Qt's QVulkanInstance (if any header pulls it in) defines
// VK_NO_PROTOTYPES.
#include <sherpa/render/comparison.h>

#include "difference_legend.h"

#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QVBoxLayout>
#include <cmath>

namespace sherpa::editor {

namespace {
constexpr int kBarWidth = 24, kBarHeight = 256;

QString eighths(double v) { // a difference in 8-bit steps, as the shader thresholds it
    return QString::number(v * 255.0, 'f', v * 255.0 < 10.0 ? 2 : 1);
}
} // namespace

DifferenceLegend::DifferenceLegend(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("differenceLegend"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);
    title_ = new QLabel(this);
    top_ = new QLabel(this);
    bar_ = new QLabel(this);
    bottom_ = new QLabel(this);
    numbers_ = new QLabel(this);
    numbers_->setObjectName(QStringLiteral("differenceNumbers"));
    numbers_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    for (QLabel* l : {title_, numbers_}) l->setWordWrap(true);
    // Full heat at the top: the bar reads like a chart's y axis.
    QImage bar(kBarWidth, kBarHeight, QImage::Format_RGB32);
    for (int y = 0; y < kBarHeight; ++y) {
        const auto c = render::heat_colour(1.0 - double(y) / double(kBarHeight - 1));
        for (int x = 0; x < kBarWidth; ++x) bar.setPixel(x, y, qRgb(c[0], c[1], c[2]));
    }
    bar_->setPixmap(QPixmap::fromImage(bar));
    layout->addWidget(title_);
    layout->addWidget(top_);
    layout->addWidget(bar_);
    layout->addWidget(bottom_);
    layout->addWidget(numbers_);
    layout->addStretch(1);
    setFixedWidth(170);
    retranslate();
}

QImage DifferenceLegend::colourBar() const {
    return bar_->pixmap().toImage();
}

void DifferenceLegend::setScale(float heat_max, float threshold) {
    heat_max_ = heat_max;
    threshold_ = threshold;
    retranslate();
}

void DifferenceLegend::setNumbers(const DifferenceNumbers& numbers) {
    last_ = numbers;
    showNumbers();
}

QString DifferenceLegend::scaleText() const {
    return top_->text();
}

QString DifferenceLegend::numbersText() const {
    return numbers_->text();
}

void DifferenceLegend::retranslate() {
    title_->setText(tr("|A − B|, largest of R, G, B (of 255)"));
    bottom_->setText(QStringLiteral("0"));
    showNumbers();
}

void DifferenceLegend::showNumbers() {
    // The automatic scale is the one of the frame the numbers are of.
    if (heat_max_ > 0.0f)
        top_->setText(tr("≥ %1").arg(eighths(heat_max_)));
    else
        top_->setText(last_.valid ? tr("≥ %1 (auto)").arg(eighths(last_.heat_max)) : tr("auto"));
    if (!last_.valid) {
        numbers_->setText(tr("No frame compared yet."));
        return;
    }
    const QString psnr =
        std::isinf(last_.psnr_db) ? tr("∞ (identical)") : tr("%1 dB").arg(last_.psnr_db, 0, 'f', 2);
    numbers_->setText(tr("mean %1\nmax %2\nPSNR %3\n%4% of %5 pixels over %6")
                          .arg(eighths(last_.mean), eighths(last_.max), psnr)
                          .arg(last_.over_threshold_percent, 0, 'f', 2)
                          .arg(last_.pixels)
                          .arg(eighths(threshold_)));
}

} // namespace sherpa::editor
