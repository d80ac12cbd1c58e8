#include "command_line.h"

#include "compare_controls.h"
#include "environment_menu.h"

#include <cmath>

#include <QApplication>
#include <QCommandLineParser>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QImage>
#include <QTimer>
#include <cstdio>
#include <optional>

#include "acceleration_dock.h"
#include "compare_controller.h"
#include "culling_dock.h"
#include "lab_dock.h"
#include "load_controller.h"
#include "log_dock.h"
#include "main_window.h"
#include "material_dock.h"
#include "mesh_dock.h"
#include "render_controller.h"
#include "scene_tree_dock.h"
#include "selection_controller.h"
#include "texture_dock.h"
#include "timeline_dock.h"
#include "view_catalog.h"
#include "view_controller.h"
#include "viewport_window.h"

namespace sherpa::editor {

namespace {
const QStringList kDockNames = {
    QStringLiteral("scene-tree"), QStringLiteral("mesh"),    QStringLiteral("material"),
    QStringLiteral("textures"),   QStringLiteral("culling"), QStringLiteral("log"),
    QStringLiteral("timeline"),   QStringLiteral("lab"),     QStringLiteral("acceleration")};

// By ViewportMode.
const QStringList kModeNames = {QStringLiteral("raster"), QStringLiteral("rt"),
                                QStringLiteral("split"), QStringLiteral("difference")};

// --compare-with tangents:METHOD: the method, when the name is one (to_string's).
std::optional<scene::TangentMethod> tangent_method(const QString& name) {
    scene::TangentMethod m{};
    if (!scene::parse_tangent_method(name.toStdString(), m)) return std::nullopt;
    return m;
}

// --mode and --compare-with, once the scene is loaded.
void apply_viewport_mode(MainWindow& window, const CommandLine& cl) {
    CompareState& compare = window.comparison().state();
    const QString& side = cl.compare_with;
    if (side.startsWith(QLatin1String("view:")))
        compare.setSide(SideB::OtherView, *ViewCatalog::viewId(side.mid(5)));
    else if (side.startsWith(QLatin1String("tangents:")))
        window.comparison().compareWithTangents(*tangent_method(side.mid(9))); // checked by parse
    else if (!side.isEmpty() && side != QLatin1String("rt"))
        window.comparison().compareWithFile(side); // loaded on the thread pool, then side B
    if (!cl.mode.isEmpty()) compare.setMode(static_cast<ViewportMode>(kModeNames.indexOf(cl.mode)));
}

QDockWidget* dock_named(MainWindow& w, const QString& name) {
    QDockWidget* docks[] = {w.docks().sceneTree, w.docks().mesh,    w.docks().material,
                            w.docks().textures,  w.docks().culling, w.docks().log,
                            w.docks().timeline,  w.docks().lab,     w.docks().acceleration};
    const auto i = kDockNames.indexOf(name);
    return i >= 0 ? docks[i] : nullptr;
}
} // namespace

void when_layout_settles(MainWindow& window, std::function<void()> then) {
    constexpr int kPollMs = 100;
    constexpr int kStablePolls = 3; // the same size this many polls in a row
    constexpr int kMaxPolls = 100;
    struct State {
        QSize last;
        int stable = 0, polls = 0;
        std::function<void()> then;
    };
    auto state = std::make_shared<State>(State{{}, 0, 0, std::move(then)});
    auto* timer = new QTimer(&window);
    timer->setInterval(kPollMs);
    QObject::connect(timer, &QTimer::timeout, &window, [&window, state, timer] {
        const QSize size = window.viewport()->pixelSize();
        state->stable = size == state->last ? state->stable + 1 : 0;
        state->last = size;
        const render::FrameRequest& f = window.frames().lastFrame().request;
        // Drawn at the final size, and the renderer's culling passes read back (the
        // culling dock's pass table), so that a screenshot shows them.
        const bool drawn = !window.viewport()->isExposed() || !window.frames().renderer() ||
                           (static_cast<int>(f.width) == size.width() &&
                            static_cast<int>(f.height) == size.height() &&
                            (!window.context().scene() || window.docks().culling->passRows() > 0));
        if (!drawn) window.viewport()->scheduleFrame();
        if ((state->stable >= kStablePolls && drawn) || ++state->polls >= kMaxPolls) {
            timer->stop();
            timer->deleteLater();
            state->then();
        }
    });
    timer->start();
}

bool parse_command_line(const QStringList& arguments, CommandLine& out, QString& error) {
    QCommandLineParser p;
    p.setApplicationDescription(QStringLiteral("Sherpa: a glTF 2.0 scene inspection editor."));
    p.addHelpOption();
    p.addVersionOption();
    p.addPositionalArgument(
        QStringLiteral("scene"),
        QStringLiteral("A .gltf/.glb file, builtin:default or builtin:grid?n=N."));
    const QCommandLineOption view(QStringLiteral("view"),
                                  QStringLiteral("Debug view (lit, normal, tangent, ...)."),
                                  QStringLiteral("name"));
    const QCommandLineOption shot(
        QStringLiteral("screenshot"),
        QStringLiteral("Save the window to this PNG once the scene is shown."),
        QStringLiteral("file"));
    const QCommandLineOption quit(QStringLiteral("quit"),
                                  QStringLiteral("Quit after the screenshot."));
    const QCommandLineOption language(QStringLiteral("language"),
                                      QStringLiteral("UI language: en, zh_CN, de."),
                                      QStringLiteral("code"));
    const QCommandLineOption select(QStringLiteral("select"),
                                    QStringLiteral("Select this node (name or index) once loaded."),
                                    QStringLiteral("node"));
    const QCommandLineOption timing(
        QStringLiteral("timing"),
        QStringLiteral("Print launch, load and first-frame times in ms."));
    const QCommandLineOption dock(
        QStringLiteral("dock"),
        QStringLiteral("Show and raise this dock: scene-tree, mesh, material, textures, culling, "
                       "log, timeline, lab, acceleration (may be repeated)."),
        QStringLiteral("name"));
    const QCommandLineOption gpu_culling(
        QStringLiteral("gpu-culling"),
        QStringLiteral("Cull on the GPU (Culling > Path > GPU) with the CPU/GPU agreement check."));
    const QCommandLineOption overlay(
        QStringLiteral("overlay"),
        QStringLiteral("Switch this overlay on (wireframe, normals, aabb, skeleton, ...)."),
        QStringLiteral("name"));
    const QCommandLineOption time(
        QStringLiteral("time"),
        QStringLiteral("Show the first animation at this time (seconds) once loaded."),
        QStringLiteral("seconds"));
    const QCommandLineOption rt(
        QStringLiteral("rt"),
        QStringLiteral(
            "Ray tracing where the device has it: on (default; acceleration structures "
            "built on load, the ray-traced viewport modes) or off (nothing RT is made)."),
        QStringLiteral("on|off"), QStringLiteral("on"));
    const QCommandLineOption mode(
        QStringLiteral("mode"),
        QStringLiteral("Viewport mode once loaded: raster, rt, split or difference."),
        QStringLiteral("mode"));
    const QCommandLineOption compare_with(
        QStringLiteral("compare-with"),
        QStringLiteral("Side B of split/difference: rt (the ray tracer), view:NAME (another "
                       "debug view), tangents:METHOD (this file, every primitive's tangents by "
                       "mikktspace, mikktspace-welded or lengyel) or a glTF file."),
        QStringLiteral("side"));
    const QCommandLineOption environment(
        QStringLiteral("environment"),
        QStringLiteral("Environment lighting: room (built in, the default), none, or an "
                       "equirectangular .hdr/.exr file."),
        QStringLiteral("source"));
    const QCommandLineOption environment_rotation(
        QStringLiteral("environment-rotation"),
        QStringLiteral("Turns the environment about +Y by this many degrees."),
        QStringLiteral("degrees"));
    const QCommandLineOption environment_intensity(
        QStringLiteral("environment-intensity"),
        QStringLiteral("Scales the environment's radiance."), QStringLiteral("x"));
    const QCommandLineOption background(
        QStringLiteral("background"),
        QStringLiteral("Behind the scene: environment, blurred or R,G,B (linear, 0 to 1)."),
        QStringLiteral("what"));
    const QCommandLineOption tone_map(
        QStringLiteral("tone-map"),
        QStringLiteral("Tone mapping of the lit view: neutral (Khronos PBR Neutral), aces, agx or "
                       "linear."),
        QStringLiteral("curve"));
    const QCommandLineOption exposure(
        QStringLiteral("exposure"), QStringLiteral("Exposure in stops (0 leaves radiance as is)."),
        QStringLiteral("ev"));
    p.addOptions({view, shot, quit, language, select, timing, dock, gpu_culling, overlay, time, rt,
                  mode, compare_with, environment, environment_rotation, environment_intensity,
                  background, tone_map, exposure});
    p.process(arguments);
    const QStringList positional = p.positionalArguments();
    if (positional.size() > 1) {
        error = QStringLiteral("at most one scene");
        return false;
    }
    out.scene = positional.value(0);
    out.view = p.value(view);
    out.select = p.value(select);
    out.screenshot = p.value(shot);
    out.language = p.value(language);
    out.quit = p.isSet(quit);
    out.timing = p.isSet(timing);
    out.docks = p.values(dock);
    out.gpu_culling = p.isSet(gpu_culling);
    out.overlays = p.values(overlay);
    if (p.value(rt) != QLatin1String("on") && p.value(rt) != QLatin1String("off")) {
        error = QStringLiteral("--rt needs on or off, not '%1'").arg(p.value(rt));
        return false;
    }
    out.ray_tracing = p.value(rt) == QLatin1String("on");
    out.mode = p.value(mode);
    if (!out.mode.isEmpty() && !kModeNames.contains(out.mode)) {
        error = QStringLiteral("unknown mode '%1' (one of: %2)")
                    .arg(out.mode, kModeNames.join(QStringLiteral(", ")));
        return false;
    }
    out.compare_with = p.value(compare_with);
    if (p.isSet(environment)) {
        if (p.value(environment).isEmpty()) {
            error = QStringLiteral("--environment needs room, none or a file");
            return false;
        }
        out.environment = render::parse_environment_choice(p.value(environment).toStdString());
    }
    const auto number = [&](const QCommandLineOption& o, float& into) {
        if (!p.isSet(o)) return true;
        bool ok = false;
        const double v = p.value(o).toDouble(&ok);
        if (!ok || !std::isfinite(v)) {
            error =
                QStringLiteral("--%1 needs a number, not '%2'").arg(o.names().front(), p.value(o));
            return false;
        }
        into = static_cast<float>(v);
        return true;
    };
    if (!number(environment_rotation, out.display.environmentRotation) ||
        !number(environment_intensity, out.display.environmentIntensity) ||
        !number(exposure, out.display.exposure))
        return false;
    if (out.display.environmentIntensity < 0.0f) {
        error = QStringLiteral("--environment-intensity needs a number >= 0");
        return false;
    }
    if (p.isSet(background)) {
        glm::vec3 color{};
        const auto b = render::parse_background(p.value(background).toStdString(), color);
        if (!b) {
            error = QStringLiteral("--background needs environment, blurred or R,G,B (0 to 1), "
                                   "not '%1'")
                        .arg(p.value(background));
            return false;
        }
        out.display.background = *b;
        if (*b == render::Background::Color) out.display.backgroundColor = color;
    }
    if (p.isSet(tone_map)) {
        const auto t = render::parse_tone_map(p.value(tone_map).toStdString());
        if (!t) {
            error = QStringLiteral("--tone-map needs neutral, aces, agx or linear, not '%1'")
                        .arg(p.value(tone_map));
            return false;
        }
        out.display.toneMap = *t;
    }
    if (out.compare_with.startsWith(QLatin1String("view:")) &&
        !ViewCatalog::isView(out.compare_with.mid(5))) {
        error = QStringLiteral("--compare-with: unknown view '%1'").arg(out.compare_with.mid(5));
        return false;
    }
    if (out.compare_with.startsWith(QLatin1String("tangents:")) &&
        !tangent_method(out.compare_with.mid(9))) {
        QStringList names;
        for (const scene::TangentMethod m : scene::kAllTangentMethods)
            names << CompareControls::tangentMethodName(m);
        error = QStringLiteral("--compare-with: unknown tangent method '%1' (one of: %2)")
                    .arg(out.compare_with.mid(9), names.join(QStringLiteral(", ")));
        return false;
    }
    if (p.isSet(time)) {
        bool ok = false;
        out.time = p.value(time).toDouble(&ok);
        if (!ok || !(out.time >= 0.0)) {
            error = QStringLiteral("--time needs seconds >= 0, not '%1'").arg(p.value(time));
            return false;
        }
    }
    for (const QString& o : out.overlays) {
        QStringList names;
        for (const ViewEntry& e : ViewCatalog::overlays()) names << QString::fromLatin1(e.name);
        if (!names.contains(o)) {
            error = QStringLiteral("unknown overlay '%1' (one of: %2)")
                        .arg(o, names.join(QStringLiteral(", ")));
            return false;
        }
    }
    for (const QString& d : out.docks)
        if (!kDockNames.contains(d)) {
            error = QStringLiteral("unknown dock '%1' (one of: %2)")
                        .arg(d, kDockNames.join(QStringLiteral(", ")));
            return false;
        }
    if (!out.view.isEmpty() && !ViewCatalog::isView(out.view)) {
        QStringList names;
        for (const ViewEntry& v : ViewCatalog::views()) names << QString::fromLatin1(v.name);
        error = QStringLiteral("unknown view '%1' (one of: %2)")
                    .arg(out.view, names.join(QStringLiteral(", ")));
        return false;
    }
    if (out.quit && out.screenshot.isEmpty()) {
        error = QStringLiteral("--quit needs --screenshot");
        return false;
    }
    return true;
}

void run_command_line(MainWindow& window, const CommandLine& cl, qint64 started_ns) {
    auto clock = std::make_shared<QElapsedTimer>();
    clock->start();
    const auto since_launch = [clock, started_ns] {
        return static_cast<double>(clock->nsecsElapsed() + started_ns) / 1e6;
    };
    // One-shot: neither flag becomes the setting of later plain launches.
    if (!cl.language.isEmpty() && !window.setLanguage(cl.language, false))
        std::fprintf(stderr, "sherpa: no translation for '%s'\n", qPrintable(cl.language));
    if (!cl.view.isEmpty()) window.views().setDebugView(cl.view, false);
    window.views().environmentMenu().setDisplay(cl.display);
    if (cl.environment) window.views().environmentMenu().setChoice(*cl.environment);
    if (cl.gpu_culling) window.views().setGpuCulling(true);
    // The Overlays menu's actions carry the overlay's name.
    for (QAction* act : window.findChildren<QAction*>())
        if (act->isCheckable() && cl.overlays.contains(act->data().toString()))
            act->setChecked(true);
    if (!cl.docks.isEmpty()) window.setLayoutRemembered(false);
    // Once the window is shown: before, its dock tab bars do not exist to switch.
    QTimer::singleShot(0, &window, [&window, docks = cl.docks, timing = cl.timing, since_launch] {
        if (timing) {
            std::printf("sherpa: window shown %.1f ms after launch\n", since_launch());
            std::fflush(stdout);
        }
        for (const QString& name : docks)
            if (QDockWidget* d = dock_named(window, name)) {
                d->show();
                d->raise();
            }
    });
    // Always in the log dock; on stdout with --timing.
    QObject::connect(
        &window.frames(), &RenderController::firstFrame, &window, [&window, since_launch] {
            window.docks().log->append(
                LogDock::Level::Info,
                QCoreApplication::translate("sherpa::editor::CommandLine",
                                            "First frame of the scene %1 ms after launch.")
                    .arg(since_launch(), 0, 'f', 1));
        });
    if (cl.timing) {
        QObject::connect(&window.loads(), &LoadController::sceneLoaded, &window,
                         [since_launch](const QString& spec, double ms) {
                             std::printf("sherpa: %s loaded in %.1f ms (%.1f ms after launch)\n",
                                         qPrintable(spec), ms, since_launch());
                             std::fflush(stdout);
                         });
        QObject::connect(&window.frames(), &RenderController::firstFrame, &window, [since_launch] {
            std::printf("sherpa: first frame of the scene %.1f ms after launch\n", since_launch());
            std::fflush(stdout);
        });
    }
    if (!cl.select.isEmpty())
        QObject::connect(&window.loads(), &LoadController::sceneLoaded, &window, [&window, cl] {
            if (!window.selection().selectNodeNamed(cl.select))
                std::fprintf(stderr, "sherpa: no node '%s'\n", qPrintable(cl.select));
        });
    if (!cl.mode.isEmpty() || !cl.compare_with.isEmpty())
        QObject::connect(
            &window.loads(), &LoadController::sceneLoaded, &window,
            [&window, cl] { apply_viewport_mode(window, cl); }, Qt::SingleShotConnection);
    if (cl.time >= 0.0)
        QObject::connect(&window.loads(), &LoadController::sceneLoaded, &window,
                         [&window, t = cl.time] { window.docks().timeline->scrubTo(t); });
    if (!cl.screenshot.isEmpty()) {
        auto failed = std::make_shared<bool>(false);
        const auto shoot = [&window, cl, failed] {
            // Not a fixed delay: that raced the docks' resize of the viewport, and the
            // same command framed the scene at two zooms in two runs.
            when_layout_settles(window, [&window, cl, failed] {
                const QImage image = window.screenshot();
                const bool saved = image.save(cl.screenshot, "PNG");
                std::fprintf(stderr, "sherpa: screenshot %s (%dx%d) %s\n",
                             qPrintable(cl.screenshot), image.width(), image.height(),
                             saved ? "saved" : "NOT saved");
                if (cl.quit) QCoreApplication::exit(!saved ? 3 : *failed ? 1 : 0);
            });
        };
        QObject::connect(&window.loads(), &LoadController::sceneLoaded, &window, shoot,
                         Qt::SingleShotConnection);
        QObject::connect(
            &window.loads(), &LoadController::loadFailed, &window,
            [shoot, failed] {
                *failed = true;
                shoot();
            },
            Qt::SingleShotConnection);
    }
    window.loads().openScene(cl.scene.isEmpty() ? QStringLiteral("builtin:default") : cl.scene);
}

} // namespace sherpa::editor
