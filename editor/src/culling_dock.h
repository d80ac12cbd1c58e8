#pragma once
// Dock 5: live numbers of the last culling pass and a scrolling history chart.
#include <QDockWidget>

#include <array>
#include <vector>

#include <sherpa/scene/culling_passes.h>

class QChart;
class QChartView;
class QLabel;
class QLineSeries;
class QTableWidget;
class QValueAxis;

namespace sherpa::editor {

class CullingMonitor;

class CullingDock : public QDockWidget {
    Q_OBJECT
public:
    explicit CullingDock(const CullingMonitor& monitor, QWidget* parent = nullptr);
    void retranslate();
    // The numbers as shown, row by row (for the tests).
    QString valueText(int row) const;
    QString agreementText() const;
    // What the renderer culled in its last frame, pass by pass (camera, then each
    // shadow cascade): the passes' table. `cached_shadows`: the cascades were not
    // redrawn this frame, their numbers are those of the frame that drew them.
    void setRendererPasses(std::vector<scene::CullStats> passes, bool cached_shadows);
    // The passes' table as shown (for the tests); empty outside it.
    QString passText(int row, int column) const;
    int passRows() const;
    enum Row {
        Total,
        Visible,
        Culled,
        FalsePositives,
        DrawCalls,
        Triangles,
        CpuMs,
        GpuMs,
        RowCount
    };

private:
    void refresh();
    void showRendererPasses(); // renderer_passes_ into the table, in the current language

    const CullingMonitor& monitor_;
    std::array<QLabel*, RowCount> names_{};
    std::array<QLabel*, RowCount> values_{};
    QLabel* agreement_;
    QLabel* passes_title_;
    QTableWidget* passes_;
    std::vector<scene::CullStats> renderer_passes_;
    bool cached_shadows_ = false;
    QLabel* method_;
    QChart* chart_;
    QChartView* chart_view_;
    QLineSeries* visible_series_;
    QLineSeries* culled_series_;
    QValueAxis* x_axis_;
    QValueAxis* y_axis_;
    std::uint64_t samples_seen_ = 0;
};

} // namespace sherpa::editor
