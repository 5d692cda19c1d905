#include "bench/growth/report.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <map>

#include <fmt/format.h>

#include "bench/growth/loglog_fit.h"

namespace fb89::growth {

namespace {

constexpr double kMiB = 1 << 20;

double total_ms(const Measurement& m) {
    return m.load.cpu_ms + m.setup.cpu_ms + m.hidden_surface.cpu_ms;
}

struct Quantity {
    const char* name;
    std::function<double(const Measurement&)> value;
};

std::vector<Quantity> quantities(uint64_t baseline) {
    return {
        {"setup_ms", [](const Measurement& m) { return m.setup.cpu_ms; }},
        {"hidden_surface_ms", [](const Measurement& m) { return m.hidden_surface.cpu_ms; }},
        {"total_ms", total_ms},
        {"peak_rss", [](const Measurement& m) { return static_cast<double>(m.peak_rss); }},
        {"peak_above_baseline",
         [baseline](const Measurement& m) {
             return static_cast<double>(m.peak_rss) - static_cast<double>(baseline);
         }},
        {"scene_bytes", [](const Measurement& m) { return static_cast<double>(m.scene_bytes); }},
    };
}

// Runs grouped by (source, method), in first-seen order, successful ones only.
std::vector<std::vector<const Measurement*>> series(const std::vector<Measurement>& runs) {
    std::vector<std::vector<const Measurement*>> out;
    std::map<std::pair<std::string, std::string>, size_t> index;
    for (const Measurement& m : runs) {
        if (!m.ok) continue;
        auto [it, added] = index.try_emplace({m.source, m.method}, out.size());
        if (added) out.emplace_back();
        out[it->second].push_back(&m);
    }
    return out;
}

// A CSV field in double quotes, its own quotes doubled.
std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string slope_text(double s) {
    return std::isnan(s) ? "-" : fmt::format("{:.2f}", s);
}

std::string runs_table(const std::vector<Measurement>& runs, uint64_t baseline_rss) {
    std::string out = fmt::format(
        "| faces | source | method | load s | set-up s | hidden-surface s | peak MiB | "
        "scene MiB | (peak − {:.1f} MiB) / scene |\n"
        "|---:|---|---|---:|---:|---:|---:|---:|---:|\n",
        static_cast<double>(baseline_rss) / kMiB);
    for (const Measurement& m : runs) {
        if (!m.ok) {
            fmt::format_to(std::back_inserter(out), "| {} | {} | {} | failed: {} | | | | | |\n",
                           m.faces, m.source, m.method, m.failure);
            continue;
        }
        const double above = static_cast<double>(m.peak_rss) - static_cast<double>(baseline_rss);
        fmt::format_to(std::back_inserter(out),
                       "| {} | {} | {} | {:.3f} | {:.3f} | {:.3f} | {:.1f} | {:.1f} | {:.2f} |\n",
                       m.faces, m.source, m.method, m.load.cpu_ms / 1e3, m.setup.cpu_ms / 1e3,
                       m.hidden_surface.cpu_ms / 1e3, static_cast<double>(m.peak_rss) / kMiB,
                       static_cast<double>(m.scene_bytes) / kMiB,
                       above / static_cast<double>(m.scene_bytes));
    }
    return out;
}

std::string slopes_table(const std::vector<Slope>& slopes, uint64_t baseline_rss) {
    if (slopes.empty()) return "One rung per method: no slopes.\n";
    std::string out =
        "Log-log slopes against faces (CPU times), over every rung / over the top three rungs "
        "(1 = linear):\n\n| source | method | set-up | hidden-surface | total | peak memory | "
        "peak above baseline | input (scene bytes) |\n|---|---|---|---|---|---|---|---|\n";
    const size_t per_series = quantities(baseline_rss).size();  // fit_slopes() keeps this order
    for (size_t i = 0; i + per_series <= slopes.size(); i += per_series) {
        fmt::format_to(std::back_inserter(out), "| {} | {} |", slopes[i].source, slopes[i].method);
        for (size_t q = 0; q < per_series; ++q)
            fmt::format_to(std::back_inserter(out), " {} / {} |", slope_text(slopes[i + q].all),
                           slope_text(slopes[i + q].top));
        out += "\n";
    }
    return out;
}

std::string verdict_lines(const std::vector<Slope>& slopes) {
    std::string out;
    for (const MemoryVerdict& v : memory_verdicts(slopes))
        fmt::format_to(std::back_inserter(out),
                       "- {}: peak memory above baseline grows as faces^{:.2f} over the top rungs, "
                       "its input as faces^{:.2f}: {}\n",
                       v.method, v.memory_slope, v.input_slope,
                       v.faster_than_input ? "FASTER than its input" : "no faster than its input");
    return out;
}

// Each OBJ rung beside the generator's run of the same rung and method.
std::string obj_lines(const std::vector<Measurement>& runs) {
    std::string out;
    for (const Measurement& o : runs) {
        if (o.source != "obj" || !o.ok) continue;
        auto g = std::find_if(runs.begin(), runs.end(), [&](const Measurement& m) {
            return m.source == "generator" && m.ok && m.faces == o.faces && m.method == o.method;
        });
        if (g == runs.end()) continue;
        fmt::format_to(std::back_inserter(out),
                       "- {} faces from a {:.1f} MiB OBJ file, {}: load {:.2f} s (generator "
                       "{:.2f} s), peak {:.1f} MiB (generator {:.1f} MiB)\n",
                       o.faces, static_cast<double>(o.file_bytes) / kMiB, o.method,
                       o.load.cpu_ms / 1e3, g->load.cpu_ms / 1e3,
                       static_cast<double>(o.peak_rss) / kMiB,
                       static_cast<double>(g->peak_rss) / kMiB);
    }
    return out;
}

}  // namespace

std::vector<Slope> fit_slopes(const std::vector<Measurement>& runs, uint64_t baseline_rss) {
    std::vector<Slope> slopes;
    for (const auto& s : series(runs)) {
        if (s.size() < 2) continue;  // one rung (the OBJ file's): no slope
        const double largest = static_cast<double>(s.back()->faces);
        for (const Quantity& q : quantities(baseline_rss)) {
            std::vector<double> x, y, x_top, y_top;
            for (const Measurement* m : s) {
                const double f = static_cast<double>(m->faces);
                x.push_back(f);
                y.push_back(q.value(*m));
                if (f * 16 >= largest) {  // the top three rungs (4^k apart)
                    x_top.push_back(f);
                    y_top.push_back(q.value(*m));
                }
            }
            slopes.push_back({s.front()->source, s.front()->method, q.name, loglog_slope(x, y),
                              loglog_slope(x_top, y_top), static_cast<int>(x.size()),
                              static_cast<int>(x_top.size())});
        }
    }
    return slopes;
}

std::vector<MemoryVerdict> memory_verdicts(const std::vector<Slope>& slopes) {
    std::vector<MemoryVerdict> out;
    for (const Slope& memory : slopes) {
        if (memory.source != "generator" || memory.quantity != "peak_above_baseline") continue;
        auto input = std::find_if(slopes.begin(), slopes.end(), [&](const Slope& s) {
            return s.source == memory.source && s.method == memory.method &&
                   s.quantity == "scene_bytes";
        });
        if (input == slopes.end() || std::isnan(memory.top) || std::isnan(input->top)) continue;
        out.push_back(
            {memory.method, memory.top, input->top, memory.top > input->top + kMemorySlopeMargin});
    }
    return out;
}

std::string runs_csv(const std::vector<Measurement>& runs, uint64_t baseline_rss) {
    std::string out =
        "source,method,faces,loaded_faces,scene_bytes,file_bytes,load_ms,setup_ms,"
        "hidden_surface_ms,total_ms,load_wall_ms,setup_wall_ms,hidden_surface_wall_ms,"
        "peak_rss_bytes,baseline_rss_bytes,pieces,commands,ok,failure\n";
    for (const Measurement& m : runs)
        fmt::format_to(
            std::back_inserter(out),
            "{},{},{},{},{},{},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{},{},{},"
            "{},{},{}\n",
            m.source, m.method, m.faces, m.loaded_faces, m.scene_bytes, m.file_bytes, m.load.cpu_ms,
            m.setup.cpu_ms, m.hidden_surface.cpu_ms, total_ms(m), m.load.wall_ms, m.setup.wall_ms,
            m.hidden_surface.wall_ms, m.peak_rss, baseline_rss, m.pieces, m.commands, m.ok ? 1 : 0,
            quoted(m.failure));
    return out;
}

std::string slopes_csv(const std::vector<Slope>& slopes) {
    std::string out = "source,method,quantity,slope_all,slope_top,points_all,points_top\n";
    for (const Slope& s : slopes)
        fmt::format_to(std::back_inserter(out), "{},{},{},{:.4f},{:.4f},{},{}\n", s.source,
                       s.method, s.quantity, s.all, s.top, s.points_all, s.points_top);
    return out;
}

std::string markdown(const std::vector<Measurement>& runs, const std::vector<Slope>& slopes,
                     uint64_t baseline_rss) {
    return runs_table(runs, baseline_rss) + "\n" + slopes_table(slopes, baseline_rss) + "\n" +
           verdict_lines(slopes) + obj_lines(runs);
}

}  // namespace fb89::growth
