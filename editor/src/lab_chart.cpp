#include "lab_chart.h"

#include <QChart>
#include <QCoreApplication>
#include <QCursor>
#include <QGraphicsTextItem>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QScatterSeries>
#include <QTextDocument>
#include <QToolTip>
#include <QValueAxis>

#include <algorithm>
#include <limits>

#include <sherpa/lab/report_export.h>

namespace sherpa::editor {

bool wants_log_axis(double lo, double hi) {
    return lo > 0.0 && hi > 10.0 * lo;
}

namespace {

struct AxisRange {
    double min_positive = std::numeric_limits<double>::max();
    double min = std::numeric_limits<double>::max();
    double max = 0.0;
    bool log = false;
    double floor = 0.0; // where zeros sit on a log axis

    void add(double v) {
        if (v > 0.0) min_positive = std::min(min_positive, v);
        min = std::min(min, v);
        max = std::max(max, v);
    }
    void decide() {
        if (min_positive > max) min_positive = max > 0.0 ? max : 1.0;
        log = wants_log_axis(min_positive, max);
        floor = min_positive / 2.0;
    }
    double place(double v) const { return log && v <= 0.0 ? floor : v; }
};

QAbstractAxis* make_axis(const AxisRange& r, const QString& title) {
    if (r.log) {
        auto* axis = new QLogValueAxis;
        axis->setBase(10.0);
        axis->setLabelFormat(QStringLiteral("%.3g"));
        axis->setRange(r.floor / 1.5, r.max * 1.5);
        axis->setTitleText(title);
        return axis;
    }
    auto* axis = new QValueAxis;
    // Start at 0 only when the values come near it (as lab::report_svg).
    const double lo = r.min < 0.5 * r.max ? 0.0 : r.min;
    const double pad = std::max((r.max - lo) * 0.1, std::max(r.max, 1e-9) * 0.02);
    if (r.max <= 0.0)
        axis->setRange(0.0, 1.0); // every value 0 (no false positive): 0 at the bottom
    else
        axis->setRange(std::max(0.0, lo - pad), r.max + pad);
    axis->setLabelFormat(QStringLiteral("%.3g"));
    axis->setTitleText(title);
    return axis;
}

} // namespace

std::vector<std::optional<QRectF>> place_labels(const std::vector<QPointF>& anchors,
                                                const std::vector<QSizeF>& sizes,
                                                const QRectF& area,
                                                const std::vector<QRectF>& obstacles) {
    constexpr double kGap = 10.0; // from the point's centre: past the in-use ring
    std::vector<std::optional<QRectF>> out(anchors.size());
    std::vector<QRectF> placed = obstacles;
    const auto free = [&](const QRectF& box) {
        if (!area.contains(box)) return false;
        for (const QRectF& other : placed)
            if (other.intersects(box)) return false;
        return true;
    };
    for (std::size_t i = 0; i < anchors.size() && i < sizes.size(); ++i) {
        const QPointF p = anchors[i];
        const QSizeF size = sizes[i];
        if (size.height() <= 0.0) continue;
        const QRectF right(QPointF(p.x() + kGap, p.y() - size.height() / 2), size);
        const QRectF left(QPointF(p.x() - kGap - size.width(), p.y() - size.height() / 2), size);
        // Rows of the label's height up and down from the point, nearest first.
        const int rows = static_cast<int>(area.height() / size.height()) + 1;
        for (int k = 0; k <= rows && !out[i]; ++k)
            for (const double dy : {-k * size.height(), k * size.height()}) {
                if (free(right.translated(0.0, dy))) {
                    out[i] = right.translated(0.0, dy);
                    break;
                }
                if (free(left.translated(0.0, dy))) {
                    out[i] = left.translated(0.0, dy);
                    break;
                }
            }
        if (out[i]) placed.push_back(*out[i]);
    }
    return out;
}

void clear_lab_chart(QChart& chart, LabChartLabels& labels) {
    for (const QPointer<QGraphicsTextItem>& label : labels) delete label.data();
    labels.clear();
    chart.removeAllSeries();
    for (QAbstractAxis* axis : chart.axes()) {
        chart.removeAxis(axis);
        delete axis;
    }
}

std::vector<QScatterSeries*> show_lab_report(QChart& chart, const lab::FamilyReport& report,
                                             const QString& method_in_use, LabChartLabels& labels) {
    clear_lab_chart(chart, labels);
    AxisRange x, y;
    std::vector<std::size_t> plotted;
    for (std::size_t i = 0; i < report.methods.size(); ++i) {
        const lab::MethodResult& m = report.methods[i];
        const lab::ErrorFigure* e = m.error(report.chart_error);
        if (!m.ran || !e) continue;
        x.add(lab::chart_x_value(report, m));
        y.add(e->value);
        plotted.push_back(i);
    }
    x.decide();
    y.decide();
    // The error's name as the chart's title: a vertical axis title does not fit a dock.
    chart.setTitle(QString::fromStdString(report.chart_error));
    QAbstractAxis* x_axis =
        make_axis(x, report.chart_x.empty() ? QCoreApplication::translate("LabChart", "time (%1)")
                                                  .arg(QString::fromStdString(report.time_unit))
                                            : QString::fromStdString(report.chart_x));
    QAbstractAxis* y_axis = make_axis(y, QString());
    chart.addAxis(x_axis, Qt::AlignBottom);
    chart.addAxis(y_axis, Qt::AlignLeft);
    auto point = [&](std::size_t i) {
        const lab::MethodResult& m = report.methods[i];
        return QPointF(x.place(lab::chart_x_value(report, m)),
                       y.place(m.error(report.chart_error)->value));
    };

    chart.legend()->hide();
    auto* front = new QLineSeries;
    front->setName(QCoreApplication::translate("LabChart", "Pareto front"));
    for (std::size_t i : lab::pareto_front(report)) front->append(point(i));
    chart.addSeries(front);
    front->attachAxis(x_axis);
    front->attachAxis(y_axis);

    std::vector<QScatterSeries*> series;
    for (std::size_t i : plotted) {
        const lab::MethodResult& m = report.methods[i];
        auto* s = new QScatterSeries;
        QString name = QString::fromStdString(m.method.name);
        if (!m.method.parameters.empty())
            name += QLatin1Char(' ') + QString::fromStdString(m.method.parameters);
        const bool in_use = !method_in_use.isEmpty() && method_in_use == m.method.name.c_str();
        if (in_use) {
            name = QCoreApplication::translate("LabChart", "%1 (in use)").arg(name);
            s->setMarkerSize(18.0);
            s->setBorderColor(Qt::black);
            s->setPen(QPen(Qt::black, 3.0));
        } else {
            s->setMarkerSize(11.0);
        }
        s->setName(name);
        s->append(point(i));
        s->setProperty("method", qulonglong(i));
        // Its name on hover too: the label may have found no room (place_labels).
        QObject::connect(s, &QScatterSeries::hovered, s, [name](const QPointF&, bool on) {
            if (on)
                QToolTip::showText(QCursor::pos(), name);
            else
                QToolTip::hideText();
        });
        chart.addSeries(s);
        s->attachAxis(x_axis);
        s->attachAxis(y_axis);
        series.push_back(s);
        auto* label = new QGraphicsTextItem(name, &chart);
        label->document()->setDocumentMargin(1.0); // the box is the text, for placing
        label->setZValue(10.0);
        label->setData(0, point(i));
        label->setData(1, QVariant::fromValue<QObject*>(s));
        labels.emplace_back(label);
    }
    // Each label beside its point, never over another (place_labels); one that finds
    // no room in the plot area is hidden, its name left in the point's tooltip.
    auto place = [&chart, labels] {
        std::vector<QPointF> anchors;
        std::vector<QSizeF> sizes;
        std::vector<QRectF> markers;
        std::vector<QGraphicsTextItem*> items;
        for (const QPointer<QGraphicsTextItem>& label : labels) {
            if (!label) continue;
            auto* s = qobject_cast<QScatterSeries*>(label->data(1).value<QObject*>());
            anchors.push_back(chart.mapToPosition(label->data(0).toPointF(), s));
            const double r = s ? s->markerSize() / 2.0 : 0.0;
            markers.emplace_back(anchors.back() - QPointF(r, r), QSizeF(2.0 * r, 2.0 * r));
            sizes.push_back(label->boundingRect().size());
            items.push_back(label.data());
        }
        const std::vector<std::optional<QRectF>> boxes =
            place_labels(anchors, sizes, chart.plotArea(), markers);
        for (std::size_t i = 0; i < items.size(); ++i) {
            items[i]->setVisible(boxes[i].has_value());
            if (boxes[i]) items[i]->setPos(boxes[i]->topLeft());
        }
    };
    if (!labels.empty()) QObject::connect(&chart, &QChart::plotAreaChanged, labels.front(), place);
    place();
    return series;
}

} // namespace sherpa::editor
