// The two validations as a library (frontend/validations.h): the modelled 1989 hosts against
// the period's published figures, and the controller's cost model against TI's data sheet.
#include "frontend/validations.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>

#include <fmt/format.h>

#include "controller_sim/controller.h"
#include "controller_sim/gsp_board.h"
#include "controller_sim/gsp_listing.h"
#include "experiments/controller_validation.h"
#include "experiments/measure.h"
#include "frontend/common.h"
#include "frontend/data_dir.h"
#include "host/scene/scene.h"
#include "period/isa.h"
#include "period/validation.h"
#include "protocol/depth_fixed.h"

namespace fb89::frontend {

namespace {

struct Row {
    const period::PublishedFigure* figure = nullptr;
    std::string profile;
    double seconds = 0, modelled = 0, error = 0;
    bool pass = false;
    uint64_t unpriced = 0;
};

std::string number4(double v) {
    return fmt::format("{:.4g}", v);
}

// The `n` instruction classes of a kernel's timed phase that take most of the modelled time
// on a profile (at its own clocks), with the rule that prices each: where to look first when
// a figure is missed.
std::string class_breakdown(const std::string& kernel, const std::string& asked,
                            const period::GuestCounts& counts, const period::HostProfile& profile,
                            int n) {
    const period::PhaseCounts* timed = counts.phase(static_cast<int>(period::Phase::HiddenSurface));
    struct Share {
        std::string key;
        uint64_t executions;
        period::KeyPrice price;
        double us;
    };
    std::vector<Share> shares;
    double total_us = 0;
    for (const auto& [key, executions] : timed->classes) {
        const period::KeyPrice k = period::price_key(profile, key);
        const double us = static_cast<double>(executions) *
                          (k.cpu / profile.cpu_clock_mhz + k.fpu / profile.fpu_clock_mhz);
        shares.push_back({key, executions, k, us});
        total_us += us;
    }
    std::sort(shares.begin(), shares.end(),
              [](const Share& a, const Share& b) { return a.us > b.us; });
    std::string out = fmt::format(
        "{} on {} at its own clocks: {:.4g} ms in the timed phase; the classes that take most:\n",
        kernel, asked, total_us / 1e3);
    for (int i = 0; i < n && i < static_cast<int>(shares.size()); ++i) {
        const Share& s = shares[static_cast<size_t>(i)];
        std::string rule = s.price.rule ? s.price.rule->source : "(no rule: the default)";
        if (rule.size() > 90) rule = rule.substr(0, 87) + "...";
        out +=
            fmt::format("  {:>5.1f}%  {:<26} {:>9} x cpu {:>4g} fpu {:>4g}  {}\n",
                        100 * s.us / total_us, s.key, s.executions, s.price.cpu, s.price.fpu, rule);
    }
    return out;
}

std::string number(double v) {
    return std::isnan(v) ? std::string("-") : fmt::format("{:.6g}", v);
}
std::string csv_number(double v) {
    return std::isnan(v) ? std::string() : fmt::format("{:.6g}", v);
}

// ---- host-validate ----

}  // namespace

namespace {

using Profiles = std::vector<std::pair<std::string, period::HostProfile>>;
using Figures = std::vector<const period::PublishedFigure*>;
using Runs = std::map<std::pair<std::string, std::string>, period::KernelRun>;  // (isa, kernel)
using Note = std::function<void(const std::string&)>;

// The profiles: those asked for, else every one a figure names, in order.
Profiles host_profiles(const HostValidationRequest& a, const period::ValidationData& data) {
    std::vector<std::string> wanted = a.profiles;
    if (wanted.empty()) {
        std::set<std::string> seen;
        for (const auto& f : data.figures)
            for (const auto& p : f.profiles)
                if (seen.insert(p).second) wanted.push_back(p);
    }
    Profiles profiles;
    for (const std::string& name : wanted) {
        try {
            profiles.emplace_back(name, period::load_host_profile(name));
        } catch (const std::runtime_error& e) {
            throw UsageError(
                std::string(a.spelling == Spelling::Option ? "--profile: " : "profile: ") +
                e.what());
        }
    }
    return profiles;
}

// The figures each profile is set beside: those naming it, by the name asked for or its
// own; a profile that no figure names (a candidate table in a file) is set beside every
// compared figure.
std::vector<Figures> figures_of(const Profiles& profiles, const period::ValidationData& data,
                                const Note& note) {
    std::vector<Figures> out;
    for (const auto& [asked, profile] : profiles) {
        Figures figures;
        for (const auto& f : data.figures)
            for (const auto& p : f.profiles)
                if (p == asked || p == profile.name) {
                    figures.push_back(&f);
                    break;
                }
        if (figures.empty()) {
            note(fmt::format("no figure names profile {}: comparing it with all", asked));
            for (const auto& f : data.figures)
                if (!f.profiles.empty()) figures.push_back(&f);
        }
        out.push_back(std::move(figures));
    }
    return out;
}

// Each kernel a compared figure needs, run once on each instruction set that needs it.
Runs run_kernels(const Profiles& profiles, const std::vector<Figures>& figures,
                 const period::ValidationData& data, const Note& note) {
    Runs runs;
    for (size_t i = 0; i < profiles.size(); ++i) {
        const period::InstructionSet& isa = period::instruction_set(profiles[i].second.isa);
        for (const period::PublishedFigure* f : figures[i]) {
            const std::pair key{std::string(isa.name), f->kernel};
            if (runs.contains(key)) continue;
            const period::ValidationKernel& k = data.kernel(f->kernel);
            note(fmt::format("running {} on the emulated {}", k.program, isa.description));
            runs.emplace(key, period::run_validation_kernel(period::find_emulator_parts(isa), k));
            const period::KernelRun& run = runs.at(key);
            const auto* timed = run.counts.phase(static_cast<int>(period::Phase::HiddenSurface));
            note(fmt::format("  {} timed instructions; it says: {}", timed->instructions,
                             run.output.substr(0, run.output.find('\n'))));
        }
    }
    return runs;
}

std::vector<Row> priced_rows(const Profiles& profiles, const std::vector<Figures>& figures,
                             const Runs& runs, const period::ValidationData& data) {
    std::vector<Row> rows;
    for (size_t i = 0; i < profiles.size(); ++i) {
        const auto& [asked, profile] = profiles[i];
        for (const period::PublishedFigure* f : figures[i]) {
            const period::ValidationKernel& k = data.kernel(f->kernel);
            const period::KernelRun& run = runs.at({profile.isa, f->kernel});
            Row r;
            r.figure = f;
            r.profile = asked;
            r.seconds = period::timed_seconds(run.counts, profile, f->clock_mhz);
            r.modelled = period::modelled_value(k, f->unit, r.seconds);
            r.error = period::relative_error(r.modelled, f->value);
            r.pass = period::passes(*f, r.error);
            r.unpriced = period::price(run.counts, profile)
                             .phases[static_cast<int>(period::Phase::HiddenSurface)]
                             .unpriced;
            rows.push_back(r);
        }
    }
    return rows;
}

std::string figure_lines(const std::vector<Row>& rows) {
    std::string table = fmt::format("{:<8} {:<14} {:>6} {:>10} {:>10} {:<8} {:>8}  {:<13} {}\n",
                                    "kernel", "profile", "clock", "modelled", "published", "unit",
                                    "error", "check", "source");
    for (const Row& r : rows) {
        const auto& f = *r.figure;
        table += fmt::format(
            "{:<8} {:<14} {:>6} {:>10} {:>10} {:<8} {:>+7.1f}%  {:<13} {} [{}]{}\n", f.kernel,
            r.profile, f.clock_mhz > 0 ? fmt::format("{:g}MHz", f.clock_mhz) : "own",
            number4(r.modelled), number4(f.value), f.unit, 100 * r.error,
            std::string(period::check_name(f.check)) +
                (f.tolerance != period::kValidationTolerance
                     ? fmt::format(" {:.0f}%", 100 * f.tolerance)
                     : "") +
                (r.pass ? "" : "!"),
            f.cite, f.id, r.unpriced ? fmt::format(" ({} executions unpriced)", r.unpriced) : "");
    }
    return table;
}

// The same benchmark on two machines, each compared with its own figure at its own clocks:
// the ratio of the machines' speeds, modelled against published. The ratios validation.json
// names are checks (their lines, their CSV rows, and whether each passed).
void checked_ratios(const std::vector<Row>& rows, const period::ValidationData& data,
                    std::string& ratios, std::string& csv, bool& all_pass) {
    const auto row_of = [&](const std::string& figure_id) -> const Row* {
        for (const Row& r : rows)
            if (r.figure->id == figure_id) return &r;
        return nullptr;
    };
    for (const period::RatioCheck& c : data.ratios) {
        const Row *one = row_of(c.numerator), *other = row_of(c.denominator);
        if (!one || !other) continue;  // a profile of it was not asked for
        const double modelled = one->modelled / other->modelled,
                     published = one->figure->value / other->figure->value;
        const double error = period::relative_error(modelled, published);
        const bool pass = std::fabs(error) <= c.tolerance;
        all_pass = all_pass && pass;
        ratios += fmt::format(
            "  {} {} / {}: modelled {:.3g}, published {:.3g} ({:+.1f}%, within {:.0f}%{}) [{}]\n",
            one->figure->kernel, one->profile, other->profile, modelled, published, 100 * error,
            100 * c.tolerance, pass ? "" : " !", c.id);
        csv += fmt::format("{},{}/{},{},ratio,{},ratio,,{:.6g},{:.6g},{:.6f},within,{},{} / {}\n",
                           one->figure->kernel, one->profile, other->profile, c.id,
                           csv_field(one->figure->benchmark), modelled, published, error,
                           pass ? "yes" : "no", one->figure->id, other->figure->id);
    }
}

// The other pairs of machines, shown for what they say, and where one machine has several
// figures of a program, how far apart those lie.
void unchecked_lines(const std::vector<Row>& rows, const period::ValidationData& data,
                     std::string& ratios, std::string& spreads) {
    std::vector<period::ModelledFigure> modelled;
    for (const Row& r : rows)
        modelled.push_back({r.figure, r.profile, r.modelled});
    for (const period::UncheckedRatio& u : period::unchecked_ratios(modelled, data.ratios)) {
        const double low = period::relative_error(u.modelled, u.published_high),
                     high = period::relative_error(u.modelled, u.published_low);
        ratios += u.pairs == 1
                      ? fmt::format("  {} {} / {}: modelled {:.3g}, published {:.3g} ({:+.1f}%)\n",
                                    u.kernel, u.numerator, u.denominator, u.modelled,
                                    u.published_low, 100 * low)
                      : fmt::format(
                            "  {} {} / {}: modelled {:.3g}, published {:.3g} to {:.3g} "
                            "over {} pairs of figures ({:+.1f}% to {:+.1f}%)\n",
                            u.kernel, u.numerator, u.denominator, u.modelled, u.published_low,
                            u.published_high, u.pairs, 100 * low, 100 * high);
    }
    for (const period::FigureSpread& f : period::figure_spreads(modelled))
        spreads += fmt::format("  {} {}: {} figures, {} to {} {} ({:.1f}% apart); modelled {}\n",
                               f.kernel, f.profile, f.figures, number4(f.low), number4(f.high),
                               f.unit, 100 * (f.high / f.low - 1), number4(f.modelled));
}

// What each profile makes of each kernel at its own clocks, in the kernel's usual unit.
std::string own_clocks(const Profiles& profiles, const Runs& runs,
                       const period::ValidationData& data) {
    std::string table = "modelled at the profiles' own clocks:\n";
    for (const auto& [asked, profile] : profiles) {
        std::string line;
        for (const auto& [isa_kernel, run] : runs) {
            const auto& [isa, kernel] = isa_kernel;
            if (isa != profile.isa) continue;
            const period::ValidationKernel& k = data.kernel(kernel);
            const double value =
                period::modelled_value(k, k.unit, period::timed_seconds(run.counts, profile));
            line +=
                fmt::format("{}{} {} {}", line.empty() ? "" : ", ", kernel, number4(value), k.unit);
        }
        table += fmt::format("  {}: {}\n", asked, line);
    }
    return table;
}

std::string figures_csv(const std::vector<Row>& rows) {
    std::string csv =
        "kernel,profile,figure,machine,benchmark,unit,clock_mhz,modelled,published,error,"
        "check,pass,source\n";
    for (const Row& r : rows) {
        const auto& f = *r.figure;
        csv +=
            fmt::format("{},{},{},{},{},{},{},{:.6g},{:.6g},{:.6f},{},{},{}\n", f.kernel, r.profile,
                        f.id, csv_field(f.machine), csv_field(f.benchmark), f.unit,
                        f.clock_mhz > 0 ? number4(f.clock_mhz) : "", r.modelled, f.value, r.error,
                        period::check_name(f.check), r.pass ? "yes" : "no", csv_field(f.source));
    }
    return csv;
}

// What closes the table: the figures given for context, and the key.
std::string key_lines(const period::ValidationData& data) {
    std::string table;
    std::string context;
    for (const auto& f : data.figures)
        if (f.profiles.empty())
            context += fmt::format("  {}: {} {} on {} ({})\n", f.id, number4(f.value), f.unit,
                                   f.machine, f.cite);
    if (!context.empty())
        table += "not compared (context only: see each figure's note):\n" + context;
    table += fmt::format(
        "error = modelled / published - 1; within: |error| <= the figure's tolerance, at_most: "
        "error <= +tolerance, at_least: error >= -tolerance (the tolerance {:.0f}% unless the "
        "check names its own); '!' marks a failed check. clock: the profile's cycles timed at "
        "the figure's machine's clock.\n",
        100 * period::kValidationTolerance);
    return table;
}

// Each compared figure's source, once.
std::string source_lines(const std::vector<Row>& rows) {
    std::string sources = "sources:\n";
    std::set<std::string> listed;
    for (const Row& r : rows)
        if (listed.insert(r.figure->id).second)
            sources +=
                fmt::format("  [{}] {}: {}\n", r.figure->id, r.figure->machine, r.figure->source);
    return sources;
}

}  // namespace

ValidationReport host_validation(const HostValidationRequest& a) {
    const Note note = [&](const std::string& text) {
        if (a.note) a.note(text);
    };
    const period::ValidationData data = period::builtin_validation();
    const Profiles profiles = host_profiles(a, data);
    const std::vector<Figures> figures = figures_of(profiles, data, note);
    const Runs runs = run_kernels(profiles, figures, data, note);
    const std::vector<Row> rows = priced_rows(profiles, figures, runs, data);

    ValidationReport report;
    for (const Row& r : rows)
        report.all_pass = report.all_pass && r.pass;
    std::string table = figure_lines(rows);
    std::string ratios, ratio_csv, spreads;
    checked_ratios(rows, data, ratios, ratio_csv, report.all_pass);
    unchecked_lines(rows, data, ratios, spreads);
    if (!ratios.empty())
        table += "the same program on two machines, the ratio of their figures:\n" + ratios;
    if (!spreads.empty())
        table += "one machine's several published figures of one program (compilers, systems):\n" +
                 spreads;
    table += own_clocks(profiles, runs, data) + key_lines(data);
    if (a.classes > 0)
        for (const auto& [asked, profile] : profiles)
            for (const auto& [isa_kernel, run] : runs)
                if (isa_kernel.first == profile.isa)
                    table +=
                        class_breakdown(isa_kernel.second, asked, run.counts, profile, a.classes);
    report.text = table + source_lines(rows);
    report.csv = figures_csv(rows) + ratio_csv;
    return report;
}

// ---- controller-validate ----

namespace {

// The listing executed (controller_sim/gsp_board.h) beside the model, command kind by kind:
// the demo's Z-buffer frame, then a frame of the other kinds made here (a FILL_RECT inside,
// cut and outside; a depth clear, DEPTH_SPANs inside, cut and outside; FACEs). Each kind's
// executed cycles, the model's, what the instruction cache's misses and the queue account
// for, and what is left, which must be 0. "" for a profile whose chip is not the TMS34010.
std::string executed_beside_model(const controller::CostProfile& p,
                                  const std::vector<protocol::Command>& demo, bool& all_pass) {
    if (p.gsp_chip != controller::Chip::Tms34010) return "";
    using protocol::Rgb;
    std::vector<protocol::Command> c = demo;
    const Rgb grey{90, 90, 90}, red{200, 0, 0}, green{0, 180, 0};
    const uint32_t half = protocol::depth_fixed(0.5);
    protocol::Face face;
    face.color = green;
    face.x_ref = 20;
    face.y_ref = 20;
    face.z = half;
    face.dzdx = 3000;
    face.dzdy = -2000;
    face.points = {{1000, 1000}, {30000, 4000}, {9000, 40000}};
    c.insert(c.end(),
             {protocol::FrameBegin{1, 256, 192, grey}, protocol::FillRect{10, 10, 50, 40, red},
              protocol::FillRect{-20, 180, 100, 40, red}, protocol::FillRect{300, 10, 5, 5, red},
              protocol::DepthClear{}, protocol::DepthSpan{50, 20, 200, half, -1000, red},
              protocol::DepthSpan{60, -30, 40, half, 500, green},
              protocol::DepthSpan{500, 0, 10, half, 0, red}, face, protocol::FrameEnd{}});
    controller::gsp::GspBoard board(p, fmt::format("{}.asm", p.gsp),
                                    controller::builtin_listing(p.gsp).text);
    board.execute(c);
    controller::Controller model(p);
    model.execute(c);
    std::string out = fmt::format(
        "\nThe listing executed (fb89 replay --gsp): the demo's Z-buffer frame and a frame of "
        "the other kinds, each kind's cycles as the emulated TMS34010 runs {}.asm beside the "
        "model's\n{:<12} {:>8} {:>12} {:>12} {:>11} {:>7} {:>12}\n",
        p.gsp, "command", "commands", "executed", "model", "cache miss", "queue", "unexplained");
    for (int i = 0; i < protocol::kOpcodeCount; ++i) {
        const auto& e = board.executed()[static_cast<std::size_t>(i)];
        if (e.commands == 0) continue;
        const uint64_t m = model.stats().totals[static_cast<std::size_t>(i)].cycles;
        const int64_t left = e.unexplained(m);
        all_pass = all_pass && left == 0;
        out += fmt::format("{:<12} {:>8} {:>12} {:>12} {:>11} {:>7} {:>12}{}\n",
                           protocol::to_string(protocol::kOpcodes[i]), e.commands,
                           controller::grouped(e.cycles()), controller::grouped(m),
                           controller::grouped(e.cache_miss_states), e.queue_overlapped,
                           fmt::format("{:+}", left), left == 0 ? "  ok" : "  MISSED");
    }
    return out;
}

}  // namespace

ValidationReport controller_validation(const ControllerValidationRequest& a) {
    const char* option = a.spelling == Spelling::Option ? "--profile" : "profile";
    const controller::CostProfile after = profile_option(a.profile, option);
    if (after.gsp.empty())
        throw UsageError(
            fmt::format("{}: {} gives its cycle figures itself (no \"gsp\" listing): there is no "
                        "memory-cycle model to check",
                        option, after.name));
    const controller::CostProfile before = controller::load_profile("tms34010-mame");
    const controller::CostProfile tms34020 = controller::load_profile("tms34020-40mhz");

    // The demo's Z-buffer frame, rendered here once, for the 34020 : 34010 ratio.
    host::Scene scene;
    experiments::ExperimentSettings settings;
    const host::ScreenScene screen =
        experiments::load_screen(bundled_scene("demo.json"), settings, scene);
    const auto measured =
        experiments::measure_interleaved(screen, {host::Method::ZBuffer}, 1, "demo", false);
    const auto rows =
        experiments::controller_validation(after, before, tms34020, measured.at(0).commands);

    bool all_pass = true;
    std::string table = fmt::format(
        "The controller against its sources: {} now, before it the first cost model "
        "(tms34010-mame)\n\n",
        after.name);
    std::string csv = "figure,unit,source,stated,before,after,checked,pass,before_pass\n";
    for (const auto& r : rows) {
        all_pass = all_pass && r.pass;
        const std::string verdict = !r.checked ? "" : r.pass ? "  ok" : "  MISSED";
        const std::string was = !r.checked ? "" : r.before_pass ? "" : " (missed)";
        table += fmt::format("{} ({})\n    {}{}\n    before {}{}, now {}{}\n", r.figure, r.unit,
                             r.source, r.stated.empty() ? "" : fmt::format(" -- {}", r.stated),
                             number(r.before), was, number(r.after), verdict);
        csv += fmt::format("{},{},{},{},{},{},{},{},{}\n", csv_field(r.figure), csv_field(r.unit),
                           csv_field(r.source), csv_field(r.stated), csv_number(r.before),
                           csv_number(r.after), r.checked ? "yes" : "no", r.pass ? "yes" : "no",
                           r.before_pass ? "yes" : "no");
    }
    table += executed_beside_model(after, measured.at(0).commands.commands(), all_pass);
    ValidationReport report;
    report.text = table;
    report.csv = csv;
    report.all_pass = all_pass;
    if (a.listing)
        report.listing = controller::annotated_listing(controller::builtin_listing(after.gsp),
                                                       controller::memory_timing(after));
    return report;
}

}  // namespace fb89::frontend
