#pragma once
// sherpa [SCENE] [--view NAME] [--select NODE] [--screenshot OUT.png [--quit]] [--language CODE]
//        [--timing] [--dock NAME ...] [--gpu-culling] [--rt on|off]
//        [--mode raster|rt|split|difference] [--compare-with rt|view:NAME|FILE]
//        [--environment room|none|FILE] [--environment-rotation DEG] [--environment-intensity X]
//        [--background environment|blurred|R,G,B] [--tone-map neutral|aces|agx|linear]
//        [--exposure EV]
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>

#include "gpu_viewport.h" // ViewportDisplay

namespace sherpa::editor {

class MainWindow;

struct CommandLine {
    QString scene; // empty: builtin:default
    QString view;
    QString select; // node name or index to select once the scene is loaded
    QString screenshot;
    QString language;
    bool quit = false;
    bool timing = false; // print launch/load/first-frame milliseconds to stdout
    QStringList docks;   // docks to show and raise (screenshots)
    bool gpu_culling = false;
    QStringList overlays;    // overlays to switch on (names of the engine's table)
    double time = -1.0;      // timeline time to show once loaded (seconds); < 0: the start
    bool ray_tracing = true; // --rt: ray trace where the device can (MainWindow's argument)
    QString mode;            // the viewport's mode once loaded: raster, rt, split, difference
    QString compare_with;    // side B: rt, view:NAME or a file (empty: the default, rt)
    // The environment (unset: the menu's default, the room) and the display settings
    // (the lit view's lighting and tone mapping) once the window is up.
    std::optional<render::EnvironmentChoice> environment;
    ViewportDisplay display;
};

// Returns false with `error` set on bad usage (unknown view, --quit without --screenshot...).
// --help and --version are handled by QCommandLineParser (they exit).
bool parse_command_line(const QStringList& arguments, CommandLine& out, QString& error);

// Calls `then` once the window's layout has settled, so a screenshot is the same on
// every run: the viewport has kept one size for several polls (docks, fonts and
// the selection have laid out) and the last frame drawn has exactly that size.
// Gives up waiting after about ten seconds and calls `then` anyway.
void when_layout_settles(MainWindow& window, std::function<void()> then);

// Wires the window for the command line: opens the scene, and with --screenshot saves
// the window once the scene is shown (and quits with --quit: exit code 0, or 1 when the
// scene failed to load, 3 when the image could not be written).
void run_command_line(MainWindow& window, const CommandLine& cl, qint64 started_ns);

} // namespace sherpa::editor
