// The report's Pareto front, CSV and SVG on a made-up report.
#include <sherpa/lab/report_export.h>

#include <gtest/gtest.h>

namespace {

using namespace sherpa::lab;

MethodResult method(std::string name, double time, double error, std::string group = "",
                    bool ran = true) {
    MethodResult m;
    m.method = {std::move(name), "", "", std::move(group)};
    m.ran = ran;
    m.time = time;
    m.errors.push_back({"err", error});
    return m;
}

FamilyReport report() {
    FamilyReport r;
    r.family = "demo";
    r.reference = "a <reference>";
    r.time_unit = "ns/object";
    r.chart_error = "err";
    r.methods = {method("slow-exact", 1000.0, 0.0),     method("fast-rough", 1.0, 5.0),
                 method("middle", 30.0, 1.0),           method("dominated", 40.0, 2.0),
                 method("other-group", 0.5, 0.1, "g2"), method("not-run", 0.1, 0.0, "", false)};
    return r;
}

std::size_t count(const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
    return n;
}

TEST(LabExport, ParetoFrontIsPerGroupAndSortedByTime) {
    const std::vector<std::size_t> front = pareto_front(report());
    // fast-rough (1), middle (2), slow-exact (0); other-group (4) alone in its group.
    EXPECT_EQ(front, (std::vector<std::size_t>{4, 1, 2, 0}));
    FamilyReport higher = report();
    for (MethodResult& m : higher.methods) m.errors[0].higher_is_better = true;
    // Higher is better: slow-exact (0) and middle (2) are now beaten by fast-rough.
    EXPECT_EQ(pareto_front(higher), (std::vector<std::size_t>{4, 1}));
}

TEST(LabExport, CsvHasOneRowPerMethodAndEveryFigure) {
    const std::string csv = report_csv(report());
    EXPECT_EQ(csv.substr(0, csv.find('\n')),
              "method,parameters,ran,time,time_unit,total_ms,err,failures,note");
    EXPECT_EQ(count(csv, "\n"), 7u);
    EXPECT_NE(csv.find("middle,,1,30,ns/object,0,1,0,\n"), std::string::npos) << csv;
}

TEST(LabExport, SvgPlotsRunMethodsOnLogAxesAndMarksTheFront) {
    const std::string svg = report_svg(report());
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
    EXPECT_EQ(count(svg, "<circle"), 5u) << "methods that ran";
    EXPECT_EQ(count(svg, "fill=\"#d62728\"><title>"), 4u) << "front points filled";
    EXPECT_EQ(count(svg, "<polyline"), 2u) << "one front line per group";
    EXPECT_NE(svg.find("ns/object (log)"), std::string::npos) << "time spans 3.3 decades";
    EXPECT_NE(svg.find("err (log)"), std::string::npos) << "error spans 1.7 decades";
    EXPECT_NE(svg.find("a &lt;reference&gt;"), std::string::npos) << "text escaped";
}

TEST(LabExport, LinearAxesWhereTheDataSpansLessThanADecade) {
    FamilyReport r = report();
    r.methods = {method("a", 2.0, 1.0), method("b", 3.0, 2.0)};
    const std::string svg = report_svg(r);
    EXPECT_EQ(svg.find("(log)"), std::string::npos);
}

} // namespace
