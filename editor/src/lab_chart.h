#pragma once
// The Lab's scatter chart of time against the family's chart error, drawn with Qt
// Charts as lab::report_svg draws it for the CLI: one point per method that ran, an
// axis logarithmic where its positive values span more than a decade (zeros then sit
// on the axis floor), the Pareto front joined, the method in use ringed.
#include <QPointF>
#include <QPointer>
#include <QRectF>
#include <QString>

#include <optional>
#include <vector>

#include <sherpa/lab/family.h>

class QChart;
class QGraphicsTextItem;
class QScatterSeries;

namespace sherpa::editor {

// The points' labels (method and parameters), items of the chart kept beside it.
using LabChartLabels = std::vector<QPointer<QGraphicsTextItem>>;

// Replaces `chart`'s series, axes and `labels`. Returns one series per plotted method
// with its index into report.methods as the series' "method" property; each point is
// labelled with its method (a legend would not fit a dock's width).
std::vector<QScatterSeries*> show_lab_report(QChart& chart, const lab::FamilyReport& report,
                                             const QString& method_in_use, LabChartLabels& labels);
// Removes every series, axis and label.
void clear_lab_chart(QChart& chart, LabChartLabels& labels);

// Where the labels of `sizes` go beside their points `anchors`, in order: right of
// the point, else left, else the nearest free place above or below on either side,
// every box inside `area` (so off the axes' labels) and none intersecting another or
// one of `obstacles` (the points' markers). A label with no free place gets none
// (hidden; its point keeps it as a tooltip). Overlap is never the answer: at y = 0
// every exact method of a family coincides.
std::vector<std::optional<QRectF>> place_labels(const std::vector<QPointF>& anchors,
                                                const std::vector<QSizeF>& sizes,
                                                const QRectF& area,
                                                const std::vector<QRectF>& obstacles = {});

// Whether positive values spanning [lo, hi] want a logarithmic axis (lab::report_svg's rule).
bool wants_log_axis(double lo, double hi);

} // namespace sherpa::editor
