#pragma once
// Next to the viewport in Difference mode: the heat map's colour bar (drawn with the
// engine's render::heat_colour, the colours the shader draws), its scale, and the numbers
// of the latest completed frame: mean, max, PSNR, % of pixels over the threshold.
#include <QWidget>

#include "viewport_mode.h"

class QLabel;

namespace sherpa::editor {

class DifferenceLegend : public QWidget {
    Q_OBJECT
public:
    explicit DifferenceLegend(QWidget* parent = nullptr);
    // sRGB 0..1; heat_max 0: automatic (the numbers say which).
    void setScale(float heat_max, float threshold);
    QString scaleText() const; // the top label
    void setNumbers(const DifferenceNumbers& numbers);
    QString numbersText() const;
    // The colour bar as drawn (top: full heat), for the tests.
    QImage colourBar() const;
    void retranslate();

private:
    void showNumbers();

    QLabel* title_;
    QLabel* top_;
    QLabel* bar_;
    QLabel* bottom_;
    QLabel* numbers_;
    float heat_max_ = 16.0f / 255.0f, threshold_ = 2.0f / 255.0f;
    DifferenceNumbers last_;
};

} // namespace sherpa::editor
