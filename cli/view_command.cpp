// fb89 view STREAM: plays a recorded command stream in an SDL2 window at the modelled
// controller speed (1x is the 1989 board's own time, as the cost profile models it), with
// the opcode overlay (the paper's Fig. 4.7 idea), a pixel inspector and a key panel (`h`).
// The status lines wrap to the window (controller_sim/hud_layout.h): every field is shown.
//
// Pacing: each wall-clock tick adds wall seconds x speed of modelled time to a budget;
// commands execute while the budget lasts, each spending what the controller's pipeline
// says it took (Controller::elapsed_us(): bus and execution, DESIGN.md "Controller and its
// cost model"). A stream with send times (format version 2) plays at the pace of the
// pipeline in time instead -- the host's sends, its stalls on a full command buffer
// (`--buffer`), the controller's waits for commands -- and the status line shows the frame's
// host stalls and controller idle time so far. Time between frames is not modelled, so
// frames follow each other at once.
// The stream is read incrementally (StreamReader); going back re-reads it, through the
// frame index when the stream has one. A window that would not fit the screen at --scale is
// shown at the largest scale that does (Display, fit_scale), and stderr says so. --inspect
// prints the inspector's line for given pixels at the end of the stream (for scripts).
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <thread>
#include <tuple>

#include <fmt/format.h>

#include "cli/commands.h"
#include "controller_sim/display.h"
#include "controller_sim/png_io.h"
#include "controller_sim/view_player.h"
#include "frontend/stream_tools.h"
#include "protocol/stream_reader.h"

namespace fb89::cli {

namespace {

using controller::InputEvent;
using controller::PipelineFigures;
using controller::ViewGoal;
using controller::ViewPlayer;
using Clock = std::chrono::steady_clock;

constexpr double kMaxSpeed = 1e9;  // '+' doubles the speed up to here

struct ViewArgs {
    std::string stream;
    std::string profile = std::string(controller::kDefaultProfile);
    double speed = 1;
    bool speed_given = false;
    int64_t start_call = -1, start_frame = -1;
    bool overlay = false;
    double scale = 1;
    std::string screenshot, window_screenshot, buffer;
    bool exit_at_end = false;
    bool show_keys = false;
    std::vector<std::string> inspect;  // "X,Y": print the inspector's line at the end
};

// "X,Y" of --inspect: two whole numbers from 0; a UsageError naming the option otherwise.
std::pair<uint32_t, uint32_t> parse_pixel(const std::string& text) {
    unsigned long x = 0, y = 0;
    char comma = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%lu%c%lu%c", &x, &comma, &y, &extra) != 3 || comma != ',' ||
        text.find_first_not_of("0123456789,") != std::string::npos || x > UINT32_MAX ||
        y > UINT32_MAX)
        throw UsageError(fmt::format(
            "--inspect: '{}' is not a pixel: give X,Y, two whole numbers from 0, e.g. 10,20",
            text));
    return {static_cast<uint32_t>(x), static_cast<uint32_t>(y)};
}

const std::vector<std::string> kHelp = {
    "fb89 view - keys",
    "space    play / pause",
    ".        step one command",
    "n        to the end of this frame, or the next",
    "p        previous frame (frame index)",
    "Home/End start / end of the stream",
    "+ -      speed x2 / x1/2   0: 1x = 1989 time",
    "o        overlay: tint pixels by opcode",
    "         green FILL_RECT  red DRAW_SPAN",
    "         amber DEPTH_SPAN  magenta FACE",
    "         blue FRAME_BEGIN (background)",
    "mouse    inspect the pixel under it",
    "h        hide / show these keys",
    "q, Esc   quit",
};

std::string speed_text(double speed, bool paced) {
    if (!paced) return "max";
    return speed >= 1 ? fmt::format("{:g}x", speed) : fmt::format("1/{:g}x", 1 / speed);
}

struct Ui {
    bool help = false;  // the key panel: hidden until `h`, so that it covers nothing
    bool overlay = false;
    double speed = 1;
    bool paced = true;
    bool mouse_in = false;  // the mouse is over the image, at pixel (mouse_x, mouse_y)
    uint32_t mouse_x = 0, mouse_y = 0;
    bool pinned = false;  // --inspect: the inspector stays on its pixel, whatever the mouse does
};

// The inspector's line for pixel (x, y): its colour and the command that last wrote it.
std::string inspector_text(const ViewPlayer& p, uint32_t x, uint32_t y) {
    const auto& fb = p.controller().framebuffer();
    if (x >= fb.width() || y >= fb.height())
        return fmt::format("({},{}) outside the {}x{} frame", x, y, fb.width(), fb.height());
    std::string text = fmt::format("({},{}) {}", x, y, protocol::to_string(fb.pixel(x, y)));
    if (const auto w = p.recorder().writer(x, y)) text += " by " + controller::describe(*w);
    return text;
}

// The status lines, their fields apart by two spaces (where a line wraps when the window is
// too narrow for it).
controller::Hud make_hud(const ViewPlayer& p, const Ui& ui) {
    controller::Hud hud;
    const char* state = p.at_end()                    ? "END"
                        : p.goal() == ViewGoal::Pause ? "PAUSED"
                        : p.goal() == ViewGoal::Play  ? "PLAYING"
                                                      : "SEEKING";
    hud.status.push_back(fmt::format(
        "frame {} [{}{}]  cmd {}  t {:.3f} ms in frame, {:.3f} s  {}  {}{}",
        p.frame_number() < 0 ? std::string("-") : std::to_string(p.frame_number()),
        p.frame_ordinal() + 1, p.frame_count() ? fmt::format("/{}", *p.frame_count()) : "",
        p.next_command(), p.frame_us() / 1e3, p.elapsed_us() / 1e6, speed_text(ui.speed, ui.paced),
        state, ui.overlay ? "  overlay" : ""));
    if (p.timed()) {  // the pipeline in time: who waited on whom, in this frame so far
        const PipelineFigures& f = p.pipeline_so_far();
        hud.status.push_back(fmt::format(
            "pipeline: send times {}, buffer {}  {}  controller idle {:.3f} "
            "ms  buffer high water {} bytes",
            send_times_of(p.reader()), controller::command_buffer_text(p.buffer_bytes()),
            controller::host_stall_text(p.buffer_bytes(), f.host_stalled_us / 1e3),
            std::max(0.0, p.frame_us() - f.controller_busy_us) / 1e3, f.high_water_bytes));
    }
    const auto& fb = p.controller().framebuffer();
    hud.status.push_back(ui.mouse_in && ui.mouse_x < fb.width() && ui.mouse_y < fb.height()
                             ? inspector_text(p, ui.mouse_x, ui.mouse_y)
                             : "inspector: move the mouse over the image");
    std::string last = !p.error().empty() ? "stream error: " + p.error()
                       : p.last_command() ? fmt::format("last #{} {}", p.last_number(),
                                                        protocol::to_string(*p.last_command()))
                                          : "";
    hud.status.push_back(last + (last.empty() ? "" : "  ") +
                         (ui.help ? "h: hide keys" : "h: keys"));
    hud.help = kHelp;
    hud.help_shown = ui.help;
    return hud;
}

// Applies one key; returns false to quit.
bool on_key(int key, ViewPlayer& p, Ui& ui) {
    switch (key) {
        case 'q':
        case controller::kKeyEscape:
            return false;
        case ' ':
            p.set_goal(p.goal() == ViewGoal::Play ? ViewGoal::Pause : ViewGoal::Play);
            break;
        case '.':
        case controller::kKeyRight:
            p.set_goal(ViewGoal::Pause);
            p.step();
            break;
        case 'n':
            p.next_frame();
            break;
        case 'p':
        case controller::kKeyLeft:
            p.previous_frame();
            break;
        case controller::kKeyHome:
            p.restart();
            break;
        case controller::kKeyEnd:
            p.to_end();
            break;
        case '+':
        case '=':
        case ']':
            ui.speed = std::min(ui.speed * 2, kMaxSpeed);
            ui.paced = true;
            break;
        case '-':
        case '[':
            ui.speed = std::max(ui.speed / 2, 1.0 / 1024);
            ui.paced = true;
            break;
        case '0':
            ui.speed = 1;
            ui.paced = true;
            break;
        case 'o':
            ui.overlay = !ui.overlay;
            break;
        case 'h':
            ui.help = !ui.help;
            break;
        default:
            break;
    }
    return true;
}

// Saves what the window shows of the framebuffer: the frame, tinted when the overlay is
// on; never the text.
void save_screenshot(controller::Display& display, const ViewPlayer& p, const Ui& ui,
                     const std::string& path) {
    uint32_t w = 0, h = 0;
    const std::vector<uint8_t> rgb =
        display.capture(p.controller().framebuffer(), ui.overlay ? &p.recorder() : nullptr, w, h);
    make_parent_dirs(path);
    controller::write_png(path, w, h, rgb);
}

// Saves the whole window as it shows: the frame, the status lines, the key panel if open.
void save_window_screenshot(controller::Display& display, const ViewPlayer& p, const Ui& ui,
                            const std::string& path) {
    uint32_t w = 0, h = 0;
    const std::vector<uint8_t> rgb = display.capture_window(
        p.controller().framebuffer(), ui.overlay ? &p.recorder() : nullptr, make_hud(p, ui), w, h);
    make_parent_dirs(path);
    controller::write_png(path, w, h, rgb);
}

// --start-call past the stream's last command is refused before a window opens, as dump
// refuses --calls past it (a file is counted through; stdin cannot be read twice).
void check_start_call(const ViewArgs& args) {
    if (args.start_call < 0 || args.stream == "-") return;
    protocol::StreamReader reader(args.stream);
    protocol::Command c;
    uint64_t commands = 0;
    bool damaged = false;
    try {
        while (reader.next(c))
            ++commands;
    } catch (const protocol::StreamError&) {
        damaged = true;  // the player reports the damage when it reaches it
    }
    if (static_cast<uint64_t>(args.start_call) >= commands)
        throw UsageError(
            fmt::format("--start-call: command {} is past the stream's last (it has {} {}commands)",
                        args.start_call, commands, damaged ? "readable " : ""));
}

// "--scale 2 makes a 2048x1648 window; the screen has 1280x1024: scale 1 used"
void tell_scale_fitted(const controller::ScaleFitted& f) {
    std::cerr << fmt::format(
        "fb89 view: --scale {:g} makes a {}x{} window; the screen has {}x{}: scale {:g} used\n",
        f.asked, f.window_width, f.window_height, f.screen_width, f.screen_height, f.used);
}

int run_view(const ViewArgs& args) {
    std::vector<std::pair<uint32_t, uint32_t>> inspect;
    for (const std::string& text : args.inspect)
        inspect.push_back(parse_pixel(text));
    check_start_call(args);
    ViewPlayer player(args.stream, controller::load_profile(args.profile),
                      parse_buffer_option(args.buffer, args.profile));
    if (args.start_frame >= 0) player.seek_frame_number(static_cast<uint32_t>(args.start_frame));
    if (args.start_call >= 0) player.seek_command(static_cast<uint64_t>(args.start_call));

    std::optional<controller::Display> display;
    try {
        display.emplace("fb89 view " + args.stream, args.scale, tell_scale_fitted);
    } catch (const controller::DisplayUnavailable& e) {
        std::cerr << "fb89: error: " << e.what()
                  << "; use --screenshot with xvfb-run, or fb89 replay --png\n";
        return kBadInput;
    }

    Ui ui;
    ui.overlay = args.overlay;
    ui.speed = args.speed;
    ui.paced = !(args.exit_at_end && !args.speed_given);  // a screenshot run: as fast as we can
    ui.help = args.show_keys;
    if (!inspect.empty()) {  // the HUD inspects the first pixel asked for
        ui.mouse_in = ui.pinned = true;
        std::tie(ui.mouse_x, ui.mouse_y) = inspect.front();
    }
    bool shot_taken = false;
    double budget_us = 0;
    auto last = Clock::now();
    while (true) {
        const bool busy = player.goal() != ViewGoal::Pause && !player.at_end();
        for (const InputEvent& e : display->poll(busy ? 0 : 30)) {
            if (e.kind == InputEvent::Kind::Quit) return kSuccess;
            if (e.kind == InputEvent::Kind::MouseMove && !ui.pinned) {
                const auto px = display->pixel_at(e.x, e.y);
                ui.mouse_in = px.has_value();
                if (px) std::tie(ui.mouse_x, ui.mouse_y) = *px;
            }
            if (e.kind == InputEvent::Kind::MouseLeave && !ui.pinned) ui.mouse_in = false;
            if (e.kind == InputEvent::Kind::Key && !on_key(e.key, player, ui)) return kSuccess;
        }

        // advance: paced by the modelled time, or as fast as the tick allows
        const auto now = Clock::now();
        const double wall_us = std::chrono::duration<double, std::micro>(now - last).count();
        last = now;
        const auto deadline = now + std::chrono::milliseconds(30);
        if (player.goal() == ViewGoal::Play && ui.paced) {
            budget_us = std::min(budget_us + wall_us * ui.speed, 250e3 * ui.speed);
            budget_us = player.play(budget_us, deadline);
        } else {
            budget_us = 0;
            player.run(deadline);
        }

        if (player.at_end() && !shot_taken) {
            for (const auto& [x, y] : inspect)
                std::cout << inspector_text(player, x, y) << "\n";
            std::cout.flush();
            if (!args.screenshot.empty()) save_screenshot(*display, player, ui, args.screenshot);
            if (!args.window_screenshot.empty())
                save_window_screenshot(*display, player, ui, args.window_screenshot);
            shot_taken = true;
        }
        if (player.at_end() && args.exit_at_end) {
            if (player.error().empty()) return kSuccess;
            std::cerr << "fb89 view: " << player.error() << "\n";
            return kBadInput;
        }
        display->show(player.controller().framebuffer(), ui.overlay ? &player.recorder() : nullptr,
                      make_hud(player, ui));
        if (busy) std::this_thread::sleep_until(now + std::chrono::milliseconds(16));
    }
}

}  // namespace

void register_view(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<ViewArgs>();
    CLI::App* sub = app.add_subcommand(
        "view", "Play a command stream in a window at the modelled controller speed");
    sub->add_option("stream", args->stream, "Stream file ('-' for stdin)")->required();
    sub->add_option("--profile", args->profile, profile_option_help())
        ->check(profile_validator())
        ->capture_default_str();
    auto* speed =
        sub->add_option("--speed", args->speed, "Modelled time per wall time; 1 = real 1989 time")
            ->check(CLI::Validator(
                [](const std::string& text) {
                    double v = 0;
                    std::size_t used = 0;
                    try {
                        v = std::stod(text, &used);
                    } catch (const std::exception&) {
                        used = 0;
                    }
                    return used == text.size() && v > 0 && v <= kMaxSpeed
                               ? std::string()
                               : fmt::format(
                                     "'{}' is not a speed: give a number above 0 and "
                                     "at most {:g}, e.g. 0.1 (slower) or 10 (faster)",
                                     text, kMaxSpeed);
                },
                "SPEED"))
            ->capture_default_str();
    auto* call = sub->add_option("--start-call", args->start_call, "Start at this command number")
                     ->check(CLI::NonNegativeNumber);
    sub->add_option("--start-frame", args->start_frame,
                    "Start at the FRAME_BEGIN carrying this frame number")
        ->check(CLI::NonNegativeNumber)
        ->excludes(call);
    sub->add_option("--buffer", args->buffer,
                    "A stream with send times plays at the pace of the pipeline in time with a "
                    "command buffer of this many bytes, or unbounded (default: the profile's)");
    sub->add_flag("--overlay", args->overlay, "Start with the opcode overlay on");
    sub->add_option("--scale", args->scale,
                    "Window pixels per framebuffer pixel, 0.125 to 8 (0.5: a 2048x1560 frame in "
                    "a 1024x780 window)")
        ->check(CLI::Range(0.125, 8.0))
        ->capture_default_str();
    sub->add_option("--screenshot", args->screenshot,
                    "At the end of the stream, save what the window shows of the image as PNG "
                    "(with the overlay when it is on)");
    sub->add_option("--window-screenshot", args->window_screenshot,
                    "At the end of the stream, save the whole window as PNG: the image, the "
                    "status lines and the key panel when it is open");
    sub->add_flag("--show-keys", args->show_keys,
                  "Start with the key panel open over the image (h shows and hides it)");
    sub->add_option("--inspect", args->inspect,
                    "At the end of the stream, print the inspector's line for pixel X,Y (its "
                    "colour and the command that last wrote it); may be repeated. The window's "
                    "inspector shows the first one, in place of the pixel under the mouse")
        ->type_name("X,Y")
        ->allow_extra_args(false);  // one pixel each time it is given
    sub->add_flag("--exit-at-end", args->exit_at_end,
                  "Exit at the end of the stream (as fast as possible unless --speed)");
    sub->callback([args, speed, &exit_code] {
        args->speed_given = speed->count() > 0;
        exit_code = run_view(*args);
    });
}

}  // namespace fb89::cli
