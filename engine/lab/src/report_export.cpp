#include <sherpa/lab/report_export.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace sherpa::lab {
namespace {

// The chart error of a method (0 when it lacks the figure).
double chart_value(const FamilyReport& report, const MethodResult& m) {
    const ErrorFigure* e = m.error(report.chart_error);
    return e && std::isfinite(e->value) ? e->value : 0.0;
}

bool higher_is_better(const FamilyReport& report) {
    for (const MethodResult& m : report.methods)
        if (const ErrorFigure* e = m.error(report.chart_error)) return e->higher_is_better;
    return false;
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else if (c == '"')
            out += "&quot;";
        else
            out += c;
    }
    return out;
}

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

// One axis: values to pixels, logarithmic when the positive values span a decade.
struct Axis {
    bool log = false;
    double lo = 0.0, hi = 1.0;
    double p0 = 0.0, p1 = 1.0; // pixel positions of lo and hi

    Axis(const std::vector<double>& values, double pixel_lo, double pixel_hi)
        : p0(pixel_lo), p1(pixel_hi) {
        double pmin = INFINITY, pmax = 0.0, vmin = INFINITY, vmax = -INFINITY;
        for (double v : values) {
            vmin = std::min(vmin, v), vmax = std::max(vmax, v);
            if (v > 0) pmin = std::min(pmin, v), pmax = std::max(pmax, v);
        }
        if (values.empty()) vmin = 0.0, vmax = 1.0;
        log = pmax > 0.0 && pmax / pmin > 10.0 && vmin >= 0.0;
        if (log) {
            lo = std::pow(10.0, std::floor(std::log10(pmin)) - (vmin <= 0.0 ? 1.0 : 0.0));
            hi = std::pow(10.0, std::ceil(std::log10(pmax)));
        } else {
            // From 0 when the values come near it (counts, angles); around the values
            // otherwise (PSNR between 44 and 54 dB).
            lo = vmin >= 0.0 && vmin <= 0.25 * vmax ? 0.0 : vmin, hi = vmax;
            if (hi - lo <= 0.0) hi = lo + (std::abs(lo) > 0 ? std::abs(lo) : 1.0);
            const double pad = 0.05 * (hi - lo);
            hi += pad;
            if (lo != 0.0) lo -= pad;
        }
    }
    double operator()(double v) const {
        const double t =
            log ? (std::log10(std::max(v, lo)) - std::log10(lo)) / (std::log10(hi) - std::log10(lo))
                : (v - lo) / (hi - lo);
        return p0 + t * (p1 - p0);
    }
    std::vector<double> ticks() const {
        std::vector<double> t;
        if (log)
            for (double v = lo; v <= hi * 1.0001; v *= 10.0) t.push_back(v);
        else
            for (int i = 0; i <= 5; ++i) t.push_back(lo + (hi - lo) * i / 5.0);
        return t;
    }
};

} // namespace

double chart_x_value(const FamilyReport& report, const MethodResult& m) {
    if (report.chart_x.empty()) return m.time;
    const ErrorFigure* e = m.error(report.chart_x);
    return e && std::isfinite(e->value) ? e->value : 0.0;
}

std::string chart_x_name(const FamilyReport& report) {
    return report.chart_x.empty() ? "time" : report.chart_x;
}

std::vector<std::size_t> pareto_front(const FamilyReport& report) {
    const double sign = higher_is_better(report) ? -1.0 : 1.0; // compare as lower-is-better
    std::vector<std::size_t> front;
    for (std::size_t i = 0; i < report.methods.size(); ++i) {
        const MethodResult& a = report.methods[i];
        if (!a.ran) continue;
        const double ea = sign * chart_value(report, a);
        bool beaten = false;
        for (std::size_t j = 0; j < report.methods.size() && !beaten; ++j) {
            const MethodResult& b = report.methods[j];
            if (j == i || !b.ran || b.method.group != a.method.group) continue;
            const double eb = sign * chart_value(report, b);
            const double xa = chart_x_value(report, a), xb = chart_x_value(report, b);
            beaten = xb <= xa && eb <= ea && (xb < xa || eb < ea);
        }
        if (!beaten) front.push_back(i);
    }
    std::sort(front.begin(), front.end(), [&](std::size_t x, std::size_t y) {
        return chart_x_value(report, report.methods[x]) < chart_x_value(report, report.methods[y]);
    });
    return front;
}

std::vector<std::string> error_figure_names(const FamilyReport& report) {
    std::vector<std::string> figures;
    for (const MethodResult& m : report.methods)
        for (const ErrorFigure& e : m.errors)
            if (std::find(figures.begin(), figures.end(), e.name) == figures.end())
                figures.push_back(e.name);
    return figures;
}

std::uint64_t failure_units(const MethodResult& m) {
    std::uint64_t units = 0;
    for (const Failure& f : m.failures) units += f.count;
    return units;
}

std::string report_csv(const FamilyReport& report) {
    const std::vector<std::string> figures = error_figure_names(report);
    std::ostringstream out;
    out << "method,parameters,ran,time,time_unit,total_ms";
    for (const std::string& f : figures) out << "," << f;
    out << ",failures,note\n";
    for (const MethodResult& m : report.methods) {
        out << csv_field(m.method.name) << "," << csv_field(m.method.parameters) << ","
            << (m.ran ? 1 : 0) << "," << number(m.time) << "," << report.time_unit << ","
            << number(m.total_ms);
        for (const std::string& f : figures) {
            const ErrorFigure* e = m.error(f);
            out << "," << (e ? number(e->value) : "");
        }
        out << "," << failure_units(m) << "," << csv_field(m.note) << "\n";
    }
    return out.str();
}

std::string report_svg(const FamilyReport& report, int width, int height) {
    const double left = 80, right = width - 150.0, top = 40, bottom = height - 50.0;
    std::vector<std::size_t> ran;
    std::vector<double> xs, ys;
    for (std::size_t i = 0; i < report.methods.size(); ++i)
        if (report.methods[i].ran) {
            ran.push_back(i);
            xs.push_back(chart_x_value(report, report.methods[i]));
            ys.push_back(chart_value(report, report.methods[i]));
        }
    const Axis ax(xs, left, right), ay(ys, bottom, top);
    const std::vector<std::size_t> front = pareto_front(report);
    std::ostringstream s;
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << " " << height << "\" font-family=\"sans-serif\" "
      << "font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    s << "<text x=\"" << left << "\" y=\"20\" font-size=\"14\">" << escape(report.family) << ": "
      << escape(chart_x_name(report)) << " against " << escape(report.chart_error)
      << " (reference: " << escape(report.reference) << ")</text>\n";
    s << "<path d=\"M" << left << " " << top << " V" << bottom << " H" << right
      << "\" stroke=\"black\" fill=\"none\"/>\n";
    for (double t : ax.ticks())
        s << "<text x=\"" << ax(t) << "\" y=\"" << bottom + 15 << "\" text-anchor=\"middle\">"
          << number(t) << "</text>\n";
    for (double t : ay.ticks())
        s << "<text x=\"" << left - 5 << "\" y=\"" << ay(t) + 4 << "\" text-anchor=\"end\">"
          << number(t) << "</text>\n";
    s << "<text x=\"" << (left + right) / 2 << "\" y=\"" << height - 12
      << "\" text-anchor=\"middle\">"
      << (report.chart_x.empty() ? "time, " + escape(report.time_unit) : escape(report.chart_x))
      << (ax.log ? " (log)" : "") << "</text>\n";
    s << "<text transform=\"translate(16 " << (top + bottom) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << escape(report.chart_error)
      << (ay.log ? " (log)" : "") << (higher_is_better(report) ? ", higher is better" : "")
      << "</text>\n";
    std::vector<std::string> groups; // one dashed line per group's front
    for (std::size_t i : front)
        if (std::find(groups.begin(), groups.end(), report.methods[i].method.group) == groups.end())
            groups.push_back(report.methods[i].method.group);
    for (const std::string& g : groups) {
        s << "<polyline fill=\"none\" stroke=\"#d62728\" stroke-dasharray=\"4 3\" points=\"";
        for (std::size_t i : front)
            if (report.methods[i].method.group == g)
                s << ax(chart_x_value(report, report.methods[i])) << ","
                  << ay(chart_value(report, report.methods[i])) << " ";
        s << "\"/>\n";
    }
    for (std::size_t i : ran) {
        const MethodResult& m = report.methods[i];
        const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
        const double x = ax(chart_x_value(report, m)), y = ay(chart_value(report, m));
        s << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"5\" stroke=\"#1f77b4\" fill=\""
          << (on_front ? "#d62728" : "white") << "\"><title>" << escape(m.method.name) << " "
          << escape(m.method.parameters) << ": " << number(m.time) << " "
          << escape(report.time_unit) << ", " << number(chart_value(report, m))
          << "</title></circle>\n";
        s << "<text x=\"" << x + 7 << "\" y=\"" << y - 6 << "\">" << escape(m.method.name)
          << (m.method.parameters.empty() ? "" : " " + escape(m.method.parameters)) << "</text>\n";
    }
    s << "<text x=\"" << right + 10 << "\" y=\"" << top + 10
      << "\" fill=\"#d62728\">filled: Pareto front</text>\n</svg>\n";
    return s.str();
}

} // namespace sherpa::lab
