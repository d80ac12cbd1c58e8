#include "culling_dock.h"

#include <QChart>
#include <QChartView>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineSeries>
#include <QTableWidget>
#include <QVBoxLayout>

#include <QValueAxis>
#include <utility>

#include "culling_monitor.h"

namespace sherpa::editor {

CullingDock::CullingDock(const CullingMonitor& monitor, QWidget* parent)
    : QDockWidget(parent), monitor_(monitor) {
    setObjectName(QStringLiteral("cullingDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    auto* grid = new QGridLayout;
    for (int r = 0; r < RowCount; ++r) {
        names_[r] = new QLabel(body);
        values_[r] = new QLabel(body);
        values_[r]->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        values_[r]->setTextInteractionFlags(Qt::TextSelectableByMouse);
        // Two columns of label/value pairs keep the dock short.
        grid->addWidget(names_[r], r % 4, (r / 4) * 2);
        grid->addWidget(values_[r], r % 4, (r / 4) * 2 + 1);
    }
    method_ = new QLabel(body);
    agreement_ = new QLabel(body);
    layout->addLayout(grid);
    layout->addWidget(method_);
    layout->addWidget(agreement_);
    // The renderer's own passes: at most 1 + 4 rows, so a plain table widget.
    passes_title_ = new QLabel(body);
    passes_title_->setWordWrap(true); // a long title must not widen the dock either
    passes_ = new QTableWidget(0, 9, body);
    passes_->verticalHeader()->hide();
    passes_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    passes_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    passes_->setMaximumHeight(150);
    // Eight columns must not widen the dock (and narrow the viewport): it scrolls.
    passes_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    layout->addWidget(passes_title_);
    layout->addWidget(passes_);

    chart_ = new QChart;
    visible_series_ = new QLineSeries(chart_);
    culled_series_ = new QLineSeries(chart_);
    chart_->addSeries(visible_series_);
    chart_->addSeries(culled_series_);
    x_axis_ = new QValueAxis(chart_);
    y_axis_ = new QValueAxis(chart_);
    x_axis_->setLabelFormat(QStringLiteral("%d"));
    y_axis_->setLabelFormat(QStringLiteral("%g"));
    // Few, short ticks that never truncate: Qt Charts drew every label as "…" when
    // the dock was narrower than its default tick count wants.
    x_axis_->setTickCount(5);
    y_axis_->setTickCount(3);
    for (QValueAxis* axis : {x_axis_, y_axis_}) axis->setTruncateLabels(false);
    chart_->addAxis(x_axis_, Qt::AlignBottom);
    chart_->addAxis(y_axis_, Qt::AlignLeft);
    for (QLineSeries* s : {visible_series_, culled_series_}) {
        s->attachAxis(x_axis_);
        s->attachAxis(y_axis_);
    }
    chart_->setMargins(QMargins(2, 2, 2, 2));
    chart_->legend()->setAlignment(Qt::AlignBottom);
    chart_view_ = new QChartView(chart_, body);
    chart_view_->setRenderHint(QPainter::Antialiasing);
    chart_view_->setMinimumHeight(160);
    layout->addWidget(chart_view_, 1);
    setWidget(body);
    connect(&monitor_, &CullingMonitor::updated, this, &CullingDock::refresh);
    retranslate();
}

void CullingDock::retranslate() {
    setWindowTitle(tr("Culling Statistics"));
    const QString names[RowCount] = {tr("Total"),           tr("Visible"),    tr("Culled"),
                                     tr("False positives"), tr("Draw calls"), tr("Triangles"),
                                     tr("CPU cull ms"),     tr("GPU cull ms")};
    for (int r = 0; r < RowCount; ++r) names_[r]->setText(names[r]);
    passes_->setHorizontalHeaderLabels({tr("Pass"), tr("Total"), tr("Visible"), tr("Culled"),
                                        tr("Draw calls"), tr("Triangles"), tr("CPU cull ms"),
                                        tr("GPU cull ms"), tr("Hidden")});
    showRendererPasses();
    visible_series_->setName(tr("visible"));
    culled_series_->setName(tr("culled"));
    x_axis_->setTitleText(tr("update"));
    refresh();
}

QString CullingDock::valueText(int row) const {
    return row >= 0 && row < RowCount ? values_[row]->text() : QString();
}

QString CullingDock::agreementText() const {
    return agreement_->text();
}

void CullingDock::setRendererPasses(std::vector<scene::CullStats> passes, bool cached_shadows) {
    renderer_passes_ = std::move(passes);
    cached_shadows_ = cached_shadows;
    showRendererPasses();
}

void CullingDock::showRendererPasses() {
    const std::vector<scene::CullStats>& passes = renderer_passes_;
    const bool cached_shadows = cached_shadows_;
    passes_title_->setText(
        passes.empty() ? tr("Renderer passes: none (culling off or no frame yet)")
        : cached_shadows
            ? tr("Renderer passes, last frame (cascades reused from the frame that drew them)")
            : tr("Renderer passes, last frame"));
    passes_->setRowCount(static_cast<int>(passes.size()));
    auto ms = [](double v) { return v < 0 ? QStringLiteral("—") : QString::number(v, 'f', 3); };
    for (int r = 0; r < static_cast<int>(passes.size()); ++r) {
        const scene::CullStats& c = passes[std::size_t(r)];
        // Hidden: instances of hidden nodes, neither visible nor culled (tested = total -
        // hidden): the row adds up.
        const QString cells[9] = {QString::fromStdString(c.pass),
                                  QString::number(c.total),
                                  QString::number(c.visible),
                                  QString::number(c.culled),
                                  QString::number(c.draw_calls),
                                  QString::number(c.triangles),
                                  ms(c.cpu_ms),
                                  ms(c.gpu_ms),
                                  QString::number(c.hidden)};
        for (int col = 0; col < 9; ++col) {
            QTableWidgetItem* item = passes_->item(r, col);
            if (!item) {
                passes_->setItem(r, col, item = new QTableWidgetItem);
                item->setTextAlignment(col == 0 ? Qt::AlignLeft | Qt::AlignVCenter
                                                : Qt::AlignRight | Qt::AlignVCenter);
            }
            item->setText(cells[col]);
        }
    }
}

QString CullingDock::passText(int row, int column) const {
    const QTableWidgetItem* item = passes_->item(row, column);
    return item ? item->text() : QString();
}

int CullingDock::passRows() const {
    return passes_->rowCount();
}

void CullingDock::refresh() {
    const CullSample* s = monitor_.history().latest();
    if (!s) {
        for (QLabel* v : values_) v->setText(QStringLiteral("—"));
        method_->clear();
        agreement_->setText(tr("No scene."));
        visible_series_->clear();
        culled_series_->clear();
        return;
    }
    const scene::CullStats& c = s->cpu;
    values_[Total]->setText(QString::number(c.total));
    values_[Visible]->setText(QString::number(c.visible));
    values_[Culled]->setText(QString::number(c.culled));
    values_[FalsePositives]->setText(c.false_positives < 0 ? QStringLiteral("—")
                                                           : QString::number(c.false_positives));
    values_[DrawCalls]->setText(QString::number(c.draw_calls));
    values_[Triangles]->setText(QString::number(c.triangles));
    values_[CpuMs]->setText(QString::number(c.cpu_ms, 'f', 3));
    values_[GpuMs]->setText(s->gpu_ms < 0 ? QStringLiteral("—")
                                          : QString::number(s->gpu_ms, 'f', 3));
    const std::string_view m = to_string(c.method), simd = to_string(c.simd);
    method_->setText(tr("Pass \"%1\": method %2, %3%4")
                         .arg(QString::fromStdString(c.pass))
                         .arg(QString::fromUtf8(m.data(), static_cast<qsizetype>(m.size())))
                         .arg(QString::fromUtf8(simd.data(), static_cast<qsizetype>(simd.size())))
                         .arg(s->frozen ? tr(", culling camera frozen") : QString()));
    if (s->gpu_visible < 0 || s->cpu_gpu_differences < 0)
        agreement_->setText(tr("CPU/GPU agreement: GPU path off (Culling › Path › GPU)"));
    else if (s->cpu_gpu_differences == 0)
        agreement_->setText(
            tr("CPU/GPU agreement: ✔ both keep %1 of %2").arg(s->gpu_visible).arg(c.tested));
    else
        agreement_->setText(tr("CPU/GPU agreement: ✘ %1 objects differ (CPU keeps %2, GPU %3)")
                                .arg(s->cpu_gpu_differences)
                                .arg(c.visible)
                                .arg(s->gpu_visible));

    // Rebuild the series from the ring: at most CullHistory::kCapacity points, cheap.
    const CullChartSeries series = cull_chart_series(monitor_.history());
    visible_series_->replace(series.visible);
    culled_series_->replace(series.culled);
    x_axis_->setRange(0, static_cast<double>(CullHistory::kCapacity));
    y_axis_->setRange(0, series.top);
    y_axis_->applyNiceNumbers(); // whole, readable ticks whatever the instance count
}

} // namespace sherpa::editor
