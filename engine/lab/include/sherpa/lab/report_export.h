#pragma once
// A family's report as a table (CSV) and as a chart (SVG scatter of time against the
// chart error, Pareto front marked): what `sherpa-cli lab` writes and an editor dock
// exports, from one definition.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <sherpa/lab/family.h>

namespace sherpa::lab {

// A method's x on the chart: its time, or the figure FamilyReport::chart_x names (0
// when the method lacks it).
double chart_x_value(const FamilyReport& report, const MethodResult& m);
// What chart_x_value() measures: "time", or the figure FamilyReport::chart_x names.
std::string chart_x_name(const FamilyReport& report);

// Indices into report.methods of the methods that ran and that no other method of
// their group (MethodInfo::group) beats on both chart_x_value (time unless FamilyReport::chart_x)
// and the chart error (lower x; lower error, or higher where the figure is higher-is-better),
// ordered by time.
std::vector<std::size_t> pareto_front(const FamilyReport& report);

// One row per method: method,parameters,ran,time,<unit>,total_ms, then every error
// figure named in any method (empty where a method lacks it), then failures (count
// of units) and note.
std::string report_csv(const FamilyReport& report);
// The error figure columns of report_csv() (and of the editor's table): every figure
// named in any method, in order of first appearance.
std::vector<std::string> error_figure_names(const FamilyReport& report);
// Units of work where `m` failed, over all causes: the CSV's failures column.
std::uint64_t failure_units(const MethodResult& m);

// A self-contained SVG (width x height px): one point per method that ran, time on x
// and the chart error on y, each axis logarithmic when its positive values span more
// than a decade (zeros then sit on the axis floor, marked "0"), Pareto-front points
// filled and joined, every point labelled with its method and parameters.
std::string report_svg(const FamilyReport& report, int width = 720, int height = 480);

} // namespace sherpa::lab
