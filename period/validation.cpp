#include "period/validation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace fb89::period {

namespace {

using nlohmann::json;

[[noreturn]] void validation_fail(const std::string& origin, const std::string& what) {
    throw std::runtime_error(fmt::format("{}: {}", origin, what));
}

std::string text(const json& j, const char* key, const std::string& origin, const std::string& at,
                 bool required = true) {
    if (!j.contains(key)) {
        if (required) validation_fail(origin, fmt::format("{}\"{}\" is missing", at, key));
        return "";
    }
    if (!j[key].is_string())
        validation_fail(origin, fmt::format("{}\"{}\" must be a string", at, key));
    return j[key].get<std::string>();
}

double positive(const json& j, const char* key, const std::string& origin, const std::string& at) {
    if (!j.contains(key) || !j[key].is_number())
        validation_fail(origin, fmt::format("{}\"{}\" must be a number", at, key));
    const double v = j[key].get<double>();
    if (!(v > 0)) validation_fail(origin, fmt::format("{}\"{}\" must be > 0, got {}", at, key, v));
    return v;
}

bool known_unit(const std::string& unit) {
    return unit == "Mflop/s" || unit == "kflop/s" || unit.starts_with("us/") ||
           unit.starts_with("s/");
}

}  // namespace

const ValidationKernel& ValidationData::kernel(const std::string& name) const {
    for (const ValidationKernel& k : kernels)
        if (k.name == name) return k;
    throw std::runtime_error(fmt::format("unknown validation kernel '{}'", name));
}

ValidationData parse_validation(std::string_view source, const std::string& origin) {
    json j;
    try {
        j = json::parse(source);
    } catch (const json::exception& e) {  // a syntax error, or a number too large for a double
        validation_fail(origin, std::string("not valid JSON: ") + e.what());
    }
    if (!j.is_object() || !j.contains("schema") || j["schema"] != 1)
        validation_fail(origin, "must be an object with \"schema\": 1");
    ValidationData out;
    if (!j.contains("kernels") || !j["kernels"].is_array() || j["kernels"].empty())
        validation_fail(origin, "\"kernels\" must be a non-empty list");
    for (size_t i = 0; i < j["kernels"].size(); ++i) {
        const json& k = j["kernels"][i];
        const std::string at = fmt::format("kernel {}: ", i);
        if (!k.is_object()) validation_fail(origin, at + "must be an object");
        ValidationKernel kernel;
        kernel.name = text(k, "name", origin, at);
        kernel.program = text(k, "program", origin, at);
        kernel.operations = positive(k, "operations", origin, at);
        kernel.operation = text(k, "operation", origin, at);
        kernel.unit = text(k, "unit", origin, at);
        if (!known_unit(kernel.unit))
            validation_fail(origin,
                            fmt::format("{}unit '{}' is not Mflop/s, kflop/s, us/... or s/...", at,
                                        kernel.unit));
        kernel.description = text(k, "description", origin, at, false);
        out.kernels.push_back(std::move(kernel));
    }
    if (!j.contains("figures") || !j["figures"].is_array() || j["figures"].empty())
        validation_fail(origin, "\"figures\" must be a non-empty list");
    for (size_t i = 0; i < j["figures"].size(); ++i) {
        const json& f = j["figures"][i];
        std::string at = fmt::format("figure {}: ", i);
        if (!f.is_object()) validation_fail(origin, at + "must be an object");
        PublishedFigure figure;
        figure.id = text(f, "id", origin, at);
        at = fmt::format("figure {} ({}): ", i, figure.id);
        figure.machine = text(f, "machine", origin, at);
        figure.benchmark = text(f, "benchmark", origin, at);
        figure.kernel = text(f, "kernel", origin, at);
        try {
            (void)out.kernel(figure.kernel);
        } catch (const std::runtime_error& e) {
            validation_fail(origin, at + e.what());
        }
        figure.value = positive(f, "value", origin, at);
        figure.unit = text(f, "unit", origin, at);
        if (!known_unit(figure.unit))
            validation_fail(origin,
                            fmt::format("{}unit '{}' is not Mflop/s, kflop/s, us/... or s/...", at,
                                        figure.unit));
        const std::string check = text(f, "check", origin, at, false);
        if (check.empty() || check == "within")
            figure.check = FigureCheck::Within;
        else if (check == "at_most")
            figure.check = FigureCheck::AtMost;
        else if (check == "at_least")
            figure.check = FigureCheck::AtLeast;
        else
            validation_fail(
                origin,
                fmt::format("{}\"check\" '{}' is not within, at_most or at_least", at, check));
        if (f.contains("clock_mhz")) figure.clock_mhz = positive(f, "clock_mhz", origin, at);
        figure.tolerance =
            f.contains("tolerance") ? positive(f, "tolerance", origin, at) : kValidationTolerance;
        if (figure.tolerance >= 1)
            validation_fail(origin, at + "\"tolerance\" is a fraction, e.g. 0.15 for 15%");
        figure.source = text(f, "source", origin, at);
        figure.cite = text(f, "cite", origin, at, false);
        if (figure.cite.empty()) figure.cite = figure.id;
        if (figure.source.empty()) validation_fail(origin, at + "\"source\" must name the source");
        figure.note = text(f, "note", origin, at, false);
        if (f.contains("profiles")) {
            if (!f["profiles"].is_array())
                validation_fail(origin, at + "\"profiles\" must be a list");
            for (const json& p : f["profiles"]) {
                if (!p.is_string())
                    validation_fail(origin, at + "\"profiles\" holds profile names");
                figure.profiles.push_back(p.get<std::string>());
            }
        }
        out.figures.push_back(std::move(figure));
    }
    if (j.contains("ratios")) {
        if (!j["ratios"].is_array()) validation_fail(origin, "\"ratios\" must be a list");
        for (size_t i = 0; i < j["ratios"].size(); ++i) {
            const json& r = j["ratios"][i];
            const std::string at = fmt::format("ratios[{}]: ", i);
            if (!r.is_object()) validation_fail(origin, at + "must be an object");
            RatioCheck ratio;
            ratio.id = text(r, "id", origin, at);
            ratio.numerator = text(r, "numerator", origin, at);
            ratio.denominator = text(r, "denominator", origin, at);
            ratio.tolerance = positive(r, "tolerance", origin, at);
            ratio.note = text(r, "note", origin, at, false);
            const PublishedFigure *one = nullptr, *other = nullptr;
            for (const PublishedFigure& f : out.figures) {
                if (f.id == ratio.numerator) one = &f;
                if (f.id == ratio.denominator) other = &f;
            }
            if (!one || !other)
                validation_fail(origin, fmt::format("{}no figure '{}'", at,
                                                    one ? ratio.denominator : ratio.numerator));
            if (one->kernel != other->kernel || one->unit != other->unit)
                validation_fail(origin, at + "the two figures must be of one kernel, in one unit");
            if (one->profiles.size() != 1 || other->profiles.size() != 1 || one->clock_mhz > 0 ||
                other->clock_mhz > 0)
                validation_fail(origin, at + "each figure must name one profile, at its own clock");
            out.ratios.push_back(std::move(ratio));
        }
    }
    return out;
}

const PublishedFigure& ValidationData::figure(const std::string& id) const {
    for (const PublishedFigure& f : figures)
        if (f.id == id) return f;
    throw std::runtime_error("no published figure '" + id + "'");
}

ValidationData builtin_validation() {
    return parse_validation(validation_json(), "period/validation.json");
}

double modelled_value(const ValidationKernel& kernel, const std::string& unit, double seconds) {
    if (!(seconds > 0))
        throw std::runtime_error(
            fmt::format("kernel {}: its timed phase took no modelled time", kernel.name));
    if (unit == "Mflop/s") return kernel.operations / seconds / 1e6;
    if (unit == "kflop/s") return kernel.operations / seconds / 1e3;
    if (unit.starts_with("us/")) return seconds * 1e6 / kernel.operations;
    if (unit.starts_with("s/")) return seconds / kernel.operations;
    throw std::runtime_error(fmt::format("unknown unit '{}'", unit));
}

KernelRun run_validation_kernel(const EmulatorParts& parts, const ValidationKernel& kernel) {
    GuestRun run = run_kernel(parts, find_kernel(*parts.isa, kernel.program), {});
    KernelRun out;
    out.counts = std::move(run.counts);
    out.output.assign(run.stream.begin(), run.stream.end());
    out.wall_s = run.wall_s;
    const PhaseCounts* timed = out.counts.phase(static_cast<int>(Phase::HiddenSurface));
    if (!timed || timed->entered != 1 || timed->instructions == 0)
        throw EmulatorError(
            fmt::format("kernel {} did not mark its timed phase (3) once", kernel.program));
    return out;
}

namespace {

// The rows unchecked_ratios and figure_spreads take, by program and machine, in the order of
// their first rows.
struct FigureGroup {
    const ModelledFigure* first = nullptr;
    std::vector<const ModelledFigure*> rows;
};
std::vector<FigureGroup> own_clock_groups(const std::vector<ModelledFigure>& rows) {
    std::vector<FigureGroup> groups;
    for (const ModelledFigure& r : rows) {
        const PublishedFigure& f = *r.figure;
        if (f.check != FigureCheck::Within || f.clock_mhz > 0) continue;
        const auto same = [&](const FigureGroup& g) {
            return g.first->profile == r.profile && g.first->figure->kernel == f.kernel &&
                   g.first->figure->benchmark == f.benchmark;
        };
        auto it = std::find_if(groups.begin(), groups.end(), same);
        if (it == groups.end()) it = groups.insert(groups.end(), FigureGroup{&r, {}});
        it->rows.push_back(&r);
    }
    return groups;
}

}  // namespace

std::vector<UncheckedRatio> unchecked_ratios(const std::vector<ModelledFigure>& rows,
                                             const std::vector<RatioCheck>& checks) {
    const std::vector<FigureGroup> groups = own_clock_groups(rows);
    const auto checked = [&](const FigureGroup& a, const FigureGroup& b) {
        for (const RatioCheck& c : checks)
            for (const ModelledFigure* x : a.rows)
                for (const ModelledFigure* y : b.rows)
                    if ((c.numerator == x->figure->id && c.denominator == y->figure->id) ||
                        (c.numerator == y->figure->id && c.denominator == x->figure->id))
                        return true;
        return false;
    };
    std::vector<UncheckedRatio> out;
    for (std::size_t i = 0; i < groups.size(); ++i)
        for (std::size_t k = i + 1; k < groups.size(); ++k) {
            const FigureGroup &a = groups[i], &b = groups[k];
            if (a.first->figure->kernel != b.first->figure->kernel ||
                a.first->figure->benchmark != b.first->figure->benchmark ||
                a.first->profile == b.first->profile || checked(a, b))
                continue;
            UncheckedRatio r{a.first->figure->kernel, a.first->profile, b.first->profile,
                             a.first->modelled / b.first->modelled};
            for (const ModelledFigure* x : a.rows)
                for (const ModelledFigure* y : b.rows) {
                    if (x->figure == y->figure) continue;  // one figure, two profiles
                    const double published = x->figure->value / y->figure->value;
                    r.published_low = r.pairs ? std::min(r.published_low, published) : published;
                    r.published_high = r.pairs ? std::max(r.published_high, published) : published;
                    ++r.pairs;
                }
            if (r.pairs > 0) out.push_back(r);
        }
    return out;
}

std::vector<FigureSpread> figure_spreads(const std::vector<ModelledFigure>& rows) {
    std::vector<FigureSpread> out;
    for (const FigureGroup& g : own_clock_groups(rows)) {
        if (g.rows.size() < 2) continue;
        FigureSpread s{g.first->figure->kernel,        g.first->profile,
                       g.first->figure->unit,          g.first->modelled,
                       g.first->figure->value,         g.first->figure->value,
                       static_cast<int>(g.rows.size())};
        for (const ModelledFigure* r : g.rows) {
            s.low = std::min(s.low, r->figure->value);
            s.high = std::max(s.high, r->figure->value);
        }
        out.push_back(s);
    }
    return out;
}

bool passes(FigureCheck check, double error, double tolerance) {
    switch (check) {
        case FigureCheck::Within:
            return std::fabs(error) <= tolerance;
        case FigureCheck::AtMost:
            return error <= tolerance;
        case FigureCheck::AtLeast:
            return error >= -tolerance;
    }
    return false;
}

std::string_view check_name(FigureCheck check) {
    switch (check) {
        case FigureCheck::Within:
            return "within";
        case FigureCheck::AtMost:
            return "at_most";
        case FigureCheck::AtLeast:
            return "at_least";
    }
    return "?";
}

double timed_seconds(const GuestCounts& counts, const HostProfile& profile, double clock_mhz) {
    const PhaseCost timed = price(counts, profile).phases[static_cast<int>(Phase::HiddenSurface)];
    if (clock_mhz <= 0) return timed.ms / 1e3;
    return (timed.cpu_cycles + timed.fpu_cycles) / (clock_mhz * 1e6);
}

}  // namespace fb89::period
