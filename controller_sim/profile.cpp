// Loading and checking cost profiles (see profile.h and docs/COST_MODEL.md).
//
// Every field is required except "name" (defaults to the file stem), "description" and
// "sources". Unknown keys are errors, so a misspelt field cannot silently fall back to a
// default. Errors name the file and the field.
#include "controller_sim/profile.h"

#include "controller_sim/gsp_listing.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "protocol/depth_fixed.h"

namespace fb89::controller {

namespace {

using nlohmann::json;

// Cycle figures above this are rejected: they are typos, and they keep every per-command
// cycle count of a 16384x16384 frame far inside 64 bits.
constexpr uint64_t kMaxCycleFigure = 1'000'000;
// The clock and bus rates a profile may give, per second: from one to a million million.
constexpr double kMinRate = 1, kMaxRate = 1e12;

// The value of B_bus_bytes_per_s for a bus that takes no time.
constexpr const char* kUnlimited = "unlimited";

// The value of command_buffer_bytes for a buffer without a bound.
constexpr const char* kUnbounded = "unbounded";

constexpr std::array<std::string_view, 31> kKnownKeys = {"name",
                                                         "description",
                                                         "f_cyc_hz",
                                                         "bpp",
                                                         "C_cmd",
                                                         "C_setup",
                                                         "C_op",
                                                         "C_row",
                                                         "span_as",
                                                         "C_line_setup",
                                                         "C_line_pix",
                                                         "B_bus_bytes_per_s",
                                                         "t_handshake_s",
                                                         "bytes",
                                                         "sources",
                                                         "command_buffer_bytes",
                                                         "bands",
                                                         "bus_bits",
                                                         "gsp",
                                                         "memory_cycle_states",
                                                         "wait_states",
                                                         "refresh_every_states",
                                                         "screen_transfers_per_s",
                                                         "C_line_extra",
                                                         "derived",
                                                         "byte_strobes",
                                                         "page_mode_states",
                                                         "host_port_bytes_per_s",
                                                         "depth_bits",
                                                         "gsp_chip",
                                                         "clear_as"};

// A profile's cycle figures given directly (no "gsp"), and derived from the listing (with it).
constexpr std::array<std::string_view, 5> kGivenCycles = {"C_cmd", "C_setup", "C_op",
                                                          "C_line_setup", "C_line_pix"};
constexpr std::array<std::string_view, 4> kMemoryModel = {
    "memory_cycle_states", "wait_states", "refresh_every_states", "screen_transfers_per_s"};

// The figures a band may be given for: a cycle count, a real number, or (neither) the
// command buffer; and whether more of it makes the controller dearer.
struct Bandable {
    std::string_view name;
    uint32_t CostProfile::*cycles;
    double CostProfile::*real;
    bool more_is_dear;
};
constexpr std::array<Bandable, 14> kBandable = {{
    {"gsp", nullptr, nullptr, true},
    {"wait_states", &CostProfile::wait_states, nullptr, true},
    {"refresh_every_states", &CostProfile::refresh_every_states, nullptr, false},
    {"screen_transfers_per_s", nullptr, &CostProfile::screen_transfers_per_s, true},
    {"C_line_extra", &CostProfile::c_line_extra, nullptr, true},
    {"C_cmd", &CostProfile::c_cmd, nullptr, true},
    {"C_setup", &CostProfile::c_setup, nullptr, true},
    {"C_op", &CostProfile::c_op, nullptr, true},
    {"C_row", &CostProfile::row_states, nullptr, true},
    {"C_line_setup", &CostProfile::c_line_setup, nullptr, true},
    {"C_line_pix", &CostProfile::c_line_pix, nullptr, true},
    {"B_bus_bytes_per_s", nullptr, &CostProfile::b_bus_bytes_per_s, false},
    {"t_handshake_s", nullptr, &CostProfile::t_handshake_s, true},
    {"command_buffer_bytes", nullptr, nullptr, false},
}};

const Bandable* bandable(std::string_view name) {
    for (const Bandable& b : kBandable)
        if (b.name == name) return &b;
    return nullptr;
}

bool is_known_key(std::string_view key) {
    return std::find(kKnownKeys.begin(), kKnownKeys.end(), key) != kKnownKeys.end();
}

// Reads one profile object, naming `origin` and the field in every error.
class FieldReader {
  public:
    FieldReader(const json& j, std::string_view origin) : m_json(j), m_origin(origin) {}

    [[noreturn]] void fail(std::string_view field, std::string_view what) const {
        throw std::runtime_error(
            fmt::format("profile {}: field \"{}\": {}", m_origin, field, what));
    }

    const json& require(std::string_view field) const {
        auto it = m_json.find(field);
        if (it == m_json.end()) fail(field, "missing");
        return *it;
    }

    uint32_t count(const json& v, std::string_view field, uint64_t max) const {
        if (!v.is_number_integer())
            fail(field, fmt::format("expected an integer, got {}", v.dump()));
        if (!v.is_number_unsigned() && v.get<int64_t>() < 0)
            fail(field, fmt::format("must not be negative, got {}", v.dump()));
        const uint64_t value = v.get<uint64_t>();
        if (value > max) fail(field, fmt::format("{} is larger than the limit {}", value, max));
        return static_cast<uint32_t>(value);
    }
    uint32_t cycles(std::string_view field) const {
        return count(require(field), field, kMaxCycleFigure);
    }

    double number(std::string_view field, bool allow_zero) const {
        const json& v = require(field);
        if (!v.is_number()) fail(field, fmt::format("expected a number, got {}", v.dump()));
        const double value = v.get<double>();
        if (!std::isfinite(value)) fail(field, "must be finite");
        if (value < 0) fail(field, fmt::format("must not be negative, got {}", v.dump()));
        if (value == 0 && !allow_zero) fail(field, "must be greater than zero");
        return value;
    }
    // A number in [lo, hi]: rates far outside any machine's would make every modelled time
    // infinite or zero.
    double number_in(std::string_view field, bool allow_zero, double lo, double hi) const {
        const double value = number(field, allow_zero);
        if ((value != 0 || !allow_zero) && (value < lo || value > hi))
            fail(field, fmt::format("must be {}between {:g} and {:g}, got {}",
                                    allow_zero ? "0 or " : "", lo, hi, require(field).dump()));
        return value;
    }

    // A positive number, or "unlimited": a bus that takes no time (+infinity).
    double bandwidth(std::string_view field) const {
        const json& v = require(field);
        if (v.is_string() && v.get<std::string>() == kUnlimited)
            return std::numeric_limits<double>::infinity();
        if (!v.is_number())
            fail(field, fmt::format("expected a number or \"{}\", got {}", kUnlimited, v.dump()));
        return number_in(field, false, kMinRate, kMaxRate);
    }

    std::string text(std::string_view field, std::string fallback) const {
        auto it = m_json.find(field);
        if (it == m_json.end()) return fallback;
        if (!it->is_string()) fail(field, fmt::format("expected a string, got {}", it->dump()));
        return it->get<std::string>();
    }

  private:
    const json& m_json;
    std::string_view m_origin;
};

void read_bytes(const FieldReader& r, CostProfile& p) {
    const json& bytes = r.require("bytes");
    if (!bytes.is_object()) r.fail("bytes", "expected an object of opcode name -> bytes");
    for (const auto& [key, value] : bytes.items()) {
        bool known = false, depth = false;
        for (protocol::Opcode op : protocol::kOpcodes) {
            known = known || key == protocol::to_string(op);
            depth = depth || (key == protocol::to_string(op) && protocol::is_depth_opcode(op));
        }
        if (!known) r.fail("bytes." + key, "not an opcode (FRAME_BEGIN, FILL_RECT, ...)");
        if (depth)
            r.fail("bytes." + key,
                   "a depth command's bytes follow from its words (docs/COST_MODEL.md): not given");
    }
    for (protocol::Opcode op : protocol::kOpcodes) {
        const int i = protocol::opcode_index(op);
        if (protocol::is_depth_opcode(op)) continue;
        const std::string key = protocol::to_string(op);
        auto it = bytes.find(key);  // not given: its words, as the listing reads them
        p.bytes[i] = it == bytes.end() ? 2 * protocol::kCommandRows[i].port_words
                                       : r.count(*it, "bytes." + key, 1'000'000);
    }
    for (int i = 0; i < protocol::kOpcodeCount; ++i)  // a depth command's: from its words
        if (protocol::is_depth_opcode(protocol::kOpcodes[i]))
            p.bytes[i] = 2 * protocol::kCommandRows[i].port_words;
}

void read_sources(const FieldReader& r, const json& j, CostProfile& p) {
    auto it = j.find("sources");
    if (it == j.end()) return;
    if (!it->is_object()) r.fail("sources", "expected an object of field name -> source");
    for (const auto& [key, value] : it->items()) {
        if (!is_known_key(key) && key.rfind("bytes.", 0) != 0)
            r.fail("sources." + key, "names no profile field");
        if (!value.is_string()) r.fail("sources." + key, "expected a string");
        p.sources[key] = value.get<std::string>();
    }
}

// A banded figure's value in `p`.
double band_value(const CostProfile& p, const Bandable& figure) {
    if (figure.name == "gsp") return 0;
    if (figure.cycles) return p.*figure.cycles;
    if (figure.real) return p.*figure.real;
    return static_cast<double>(p.command_buffer_bytes);
}

void read_bands(const FieldReader& r, const json& j, CostProfile& p) {
    auto it = j.find("bands");
    if (it == j.end()) return;
    if (!it->is_object()) r.fail("bands", "expected an object of field name -> band");
    for (const auto& [key, band] : it->items()) {
        const std::string field = "bands." + key;
        const Bandable* figure = bandable(key);
        if (!figure)
            r.fail(field,
                   "names no figure that can have a band (C_*, wait_states, "
                   "refresh_every_states, screen_transfers_per_s, B_bus_bytes_per_s, "
                   "t_handshake_s, command_buffer_bytes, gsp)");
        const bool derived =
            std::find(kGivenCycles.begin(), kGivenCycles.end(), key) != kGivenCycles.end();
        if (!p.gsp.empty() && derived)
            r.fail(field,
                   "a figure derived from the listing has no band of its own: the "
                   "listing's estimates have theirs (a band for \"gsp\")");
        if (p.gsp.empty() &&
            (key == "gsp" || key == "C_line_extra" ||
             std::find(kMemoryModel.begin(), kMemoryModel.end(), key) != kMemoryModel.end()))
            r.fail(field, "only a profile with \"gsp\" has this figure");
        if (key == "gsp") {
            if (!band.is_object()) r.fail(field, "expected {\"why\": ...}");
            for (const auto& [k, v] : band.items())
                if (k != "why")
                    r.fail(field + "." + k, "unknown (the listing's band has why only)");
            auto why = band.find("why");
            if (why == band.end() || !why->is_string() || why->get<std::string>().empty())
                r.fail(field + ".why", "missing: a band says why it is that wide");
            p.bands[key] = CostProfile::Band{0, 0, why->get<std::string>()};
            continue;
        }
        if (!band.is_object())
            r.fail(field, "expected {\"low\": ..., \"high\": ..., \"why\": ...}");
        const bool buffer = key == "command_buffer_bytes";
        for (const auto& [k, v] : band.items())
            if (k != "low" && k != "why" && (buffer || k != "high"))
                r.fail(field + "." + k, buffer ? "unknown (a buffer's band has low and why)"
                                               : "unknown (a band has low, high and why)");
        const auto number = [&](const char* end) {
            auto e = band.find(end);
            if (e == band.end()) r.fail(field + "." + end, "missing");
            if (!e->is_number() || !std::isfinite(e->get<double>()) || e->get<double>() < 0)
                r.fail(field + "." + end,
                       fmt::format("expected a number not below 0, got {}", e->dump()));
            return e->get<double>();
        };
        CostProfile::Band b;
        b.low = number("low");
        const double value = band_value(p, *figure);
        b.high = buffer ? value : number("high");
        auto why = band.find("why");
        if (why == band.end() || !why->is_string() || why->get<std::string>().empty())
            r.fail(field + ".why", "missing: a band says why it is that wide");
        b.why = why->get<std::string>();
        if (!(b.low <= value && value <= b.high))
            r.fail(field, fmt::format("the figure {:g} must lie within its band, {:g} to {:g}",
                                      value, b.low, b.high));
        if (buffer) {
            const uint32_t largest = p.largest_tiling_bytes();
            if (b.low != std::floor(b.low) || b.low < largest)
                r.fail(field + ".low",
                       fmt::format("expected a whole number of bytes from the largest "
                                   "command's {}, got {:g}",
                                   largest, b.low));
        } else if (figure->cycles && (b.low != std::floor(b.low) || b.high != std::floor(b.high) ||
                                      b.high > kMaxCycleFigure)) {
            r.fail(field,
                   fmt::format("a band of cycles is whole numbers up to {}", kMaxCycleFigure));
        } else if (key == "B_bus_bytes_per_s" && b.low <= 0) {
            r.fail(field + ".low", "a bus band starts above 0 bytes/s");
        }
        p.bands[key] = std::move(b);
    }
}

std::string read_text_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error(fmt::format("profile {}: cannot open the file", path.string()));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw std::runtime_error(fmt::format("profile {}: read error", path.string()));
    return text.str();
}

}  // namespace

const char* to_string(SpanAs s) {
    return s == SpanAs::Line ? "line" : "fill";
}

const char* to_string(ClearAs c) {
    return c == ClearAs::SerialRegister ? "srt" : "fill";
}

uint64_t vram_rows(uint32_t width, uint32_t height, uint32_t bpp) {
    const uint64_t pitch_bits = std::bit_ceil(uint64_t{width}) * bpp;
    return (uint64_t{height} * pitch_bits + kVramRowBits - 1) / kVramRowBits;
}

CostProfile parse_profile(std::string_view json_text, std::string_view origin,
                          std::string_view default_name) {
    json j;
    try {
        j = json::parse(json_text, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
    } catch (const json::exception& e) {  // a syntax error, or a number too large for a double
        throw std::runtime_error(fmt::format("profile {}: not valid JSON: {}", origin, e.what()));
    }
    if (!j.is_object())
        throw std::runtime_error(fmt::format("profile {}: expected an object", origin));
    const FieldReader r(j, origin);
    for (const auto& [key, value] : j.items())
        if (!is_known_key(key)) r.fail(key, "unknown field");

    CostProfile p;
    p.name = r.text("name", std::string(default_name));
    if (p.name.empty()) r.fail("name", "missing");
    p.description = r.text("description", "");
    p.f_cyc_hz = r.number_in("f_cyc_hz", false, kMinRate, kMaxRate);
    p.bpp = r.count(r.require("bpp"), "bpp", 16);
    if (p.bpp == 0 || 16 % p.bpp != 0 || (p.bpp & (p.bpp - 1)) != 0)
        r.fail("bpp", fmt::format("must be 1, 2, 4, 8 or 16, got {}", p.bpp));
    if (auto it = j.find("bus_bits"); it != j.end()) {
        p.bus_bits = r.count(*it, "bus_bits", 32);
        if (p.bus_bits != 16 && p.bus_bits != 32)
            r.fail("bus_bits", fmt::format("must be 16 or 32, got {}", p.bus_bits));
    }
    if (p.bpp > p.bus_bits)
        r.fail("bpp",
               fmt::format("a pixel of {} bits does not fit a {}-bit bus word", p.bpp, p.bus_bits));
    if (auto it = j.find("gsp"); it != j.end()) {
        if (!it->is_string() || it->get<std::string>().empty())
            r.fail("gsp", fmt::format("expected the name of a listing, got {}", it->dump()));
        p.gsp = it->get<std::string>();
        if (auto c = j.find("gsp_chip"); c != j.end()) {
            const auto chip = c->is_string() ? chip_named(c->get<std::string>()) : std::nullopt;
            if (!chip)
                r.fail("gsp_chip",
                       fmt::format("expected \"tms34010\" or \"tms34020\", got {}", c->dump()));
            p.gsp_chip = *chip;
        }
        for (std::string_view given : kGivenCycles)
            if (j.contains(given))
                r.fail(given,
                       "derived from the listing (\"gsp\") and the memory model: a "
                       "profile with \"gsp\" does not give it");
        p.memory_cycle_states =
            r.count(r.require("memory_cycle_states"), "memory_cycle_states", 64);
        if (p.memory_cycle_states == 0) r.fail("memory_cycle_states", "must be at least 1");
        p.wait_states = r.count(r.require("wait_states"), "wait_states", 64);
        p.refresh_every_states =
            r.count(r.require("refresh_every_states"), "refresh_every_states", 1'000'000);
        if (p.refresh_every_states != 0 &&
            p.refresh_every_states < 4 * (p.memory_cycle_states + p.wait_states))
            r.fail("refresh_every_states",
                   "0 (no refresh) or at least four memory cycles, so that the GSP keeps the bus");
        p.screen_transfers_per_s = r.number_in("screen_transfers_per_s", true, 1, kMaxRate);
        p.c_line_extra = r.count(r.require("C_line_extra"), "C_line_extra", 64);
        if (auto b = j.find("byte_strobes"); b != j.end()) {
            if (!b->is_boolean())
                r.fail("byte_strobes", fmt::format("expected true or false, got {}", b->dump()));
            p.byte_strobes = b->get<bool>();
        }
        if (auto pm = j.find("page_mode_states"); pm != j.end())
            p.page_mode_states = r.count(*pm, "page_mode_states", 64);
        if (p.page_mode_states > p.memory_cycle_states)
            r.fail("page_mode_states", "a page-mode cycle is no longer than a memory cycle");
        if (j.contains("host_port_bytes_per_s"))
            p.host_port_rated_bytes_per_s =
                r.number_in("host_port_bytes_per_s", false, kMinRate, kMaxRate);
        const std::string clear_as = r.text("clear_as", "fill");
        if (clear_as == "srt")
            p.clear_as = ClearAs::SerialRegister;
        else if (clear_as != "fill")
            r.fail("clear_as", "expected \"srt\" (the VRAMs' serial registers) or \"fill\"");
    } else {
        for (std::string_view model : kMemoryModel)
            if (j.contains(model))
                r.fail(model, "only a profile with \"gsp\" (a listing) has a memory model");
        for (std::string_view field : {"C_line_extra", "byte_strobes", "page_mode_states",
                                       "host_port_bytes_per_s", "gsp_chip", "clear_as"})
            if (j.contains(field)) r.fail(field, "only a profile with \"gsp\" (a listing) has it");
        p.c_cmd = r.cycles("C_cmd");
        p.c_setup = r.cycles("C_setup");
        p.c_op = r.cycles("C_op");
        p.c_line_setup = r.cycles("C_line_setup");
        p.c_line_pix = r.cycles("C_line_pix");
    }
    p.row_states = r.cycles("C_row");
    const std::string span_as = r.text("span_as", "");
    if (span_as == "line")
        p.span_as = SpanAs::Line;
    else if (span_as == "fill")
        p.span_as = SpanAs::Fill;
    else
        r.fail("span_as", span_as.empty() ? "missing" : "expected \"line\" or \"fill\"");
    p.b_bus_bytes_per_s = r.bandwidth("B_bus_bytes_per_s");
    p.t_handshake_s = r.number_in("t_handshake_s", true, 1e-15, 1.0);
    if (auto it = j.find("depth_bits"); it != j.end()) {
        p.depth_bits = r.count(*it, "depth_bits", 32);
        if (!protocol::valid_depth_bits(p.depth_bits))
            r.fail("depth_bits", fmt::format("must be 16 or 32, got {}", p.depth_bits));
    }
    read_bytes(r, p);
    if (auto it = j.find("command_buffer_bytes"); it != j.end()) {
        const uint32_t largest = p.largest_tiling_bytes();
        if (it->is_string() && it->get<std::string>() == kUnbounded) {
            p.command_buffer_bytes = kUnboundedBuffer;
        } else if (!it->is_number_unsigned() || it->get<uint64_t>() < largest ||
                   it->get<uint64_t>() > (uint64_t{1} << 40)) {
            r.fail("command_buffer_bytes",
                   fmt::format("expected \"{}\" or a whole number of bytes from the largest "
                               "command's {} to 2^40, got {}",
                               kUnbounded, largest, it->dump()));
        } else {
            p.command_buffer_bytes = it->get<uint64_t>();
        }
    }
    read_sources(r, j, p);
    read_bands(r, j, p);
    try {
        derive_figures(p);
    } catch (const std::runtime_error& e) {
        r.fail("gsp", e.what());
    }
    if (!p.bands.empty()) {
        for (const bool dear : {false, true}) {
            try {
                (void)band_end(p, dear);
            } catch (const std::runtime_error& e) {
                r.fail("bands",
                       fmt::format("at the {} end: {}", dear ? "dear" : "cheap", e.what()));
            }
        }
    }
    return p;
}

MemoryTiming memory_timing(const CostProfile& p) {
    const uint32_t m = p.memory_cycle_states + p.wait_states;  // one memory cycle, SPVS002C p. 19
    // An I/O register's cycle ignores LRDY (p. 20): no wait states.
    // A pixel written alone (PIXT): one write when it fills its word or a byte strobe takes
    // it, else a read and a write. The 34020's hidden write states instead ([UG20] Table
    // 15-2): 1 for a byte-aligned field in a long word (case 1), 2 for one that is not (case
    // 2), plus the wait states.
    const bool pixel_alone = p.bpp >= p.bus_bits || (p.byte_strobes && p.bpp >= 8);
    const uint32_t pixel_write = p.gsp_chip == Chip::Tms34020
                                     ? (pixel_alone ? 1 : 2) + p.wait_states
                                     : (pixel_alone ? m : 2 * m);
    return MemoryTiming{m, p.memory_cycle_states, pixel_write, p.gsp_chip};
}

void derive_figures(CostProfile& p) {
    p.c_row = p.row_states;
    if (p.gsp.empty()) {
        // The first cost model's rules, from its given figures: a partial word costs a whole
        // one, every set-up is FILL's, FRAME_END and a command outside the frame cost C_cmd
        // alone, and nothing is taken for the host's words or refresh.
        p.c_op_partial = p.c_op;
        p.c_frame_begin_setup = p.c_setup;
        p.c_span_fill_setup = p.c_setup;
        p.c_frame_end_setup = 0;
        p.c_host_word = 0;
        p.stolen_share = 0;
        p.host_port_bytes_per_s = std::numeric_limits<double>::infinity();
        p.outside_pays_setup = false;
        // the depth commands: priced only by a listing, or free where everything is
        p.depth_priced = p.c_cmd == 0 && p.c_setup == 0 && p.c_op == 0 && p.c_row == 0 &&
                         p.c_line_setup == 0 && p.c_line_pix == 0;
        return;
    }
    const uint32_t m = p.memory_cycle_states + p.wait_states;  // one memory cycle, SPVS002C p. 19
    const TimingEnd end = p.listing_dear    ? TimingEnd::High
                          : p.listing_cheap ? TimingEnd::Low
                                            : TimingEnd::Estimate;
    const auto paths = count_paths(builtin_listing(p.gsp), memory_timing(p), end);
    const auto path = [&](const char* name, const char* graphics) -> uint32_t {
        auto it = paths.find(name);
        if (it == paths.end())
            throw std::runtime_error(fmt::format("listing {}.asm has no @path {}", p.gsp, name));
        if (it->second.graphics != graphics)
            throw std::runtime_error(fmt::format("listing {}.asm: @path {} must run {}", p.gsp,
                                                 name, *graphics ? graphics : "no FILL or LINE"));
        return static_cast<uint32_t>(it->second.cycles);
    };
    // TIGA's call around each command is the dear end of the listing's band; the lean
    // executive, the cheap end and the estimate (docs/COST_MODEL.md, "TIGA's call")
    p.c_tiga_call = path("TIGA_CALL", "");
    p.c_cmd = path("COMMON", "") + (p.listing_dear ? p.c_tiga_call : 0);
    p.c_frame_begin_setup = path("FRAME_BEGIN:fill", "FILL");
    p.c_frame_begin_srt_setup = path("FRAME_BEGIN", "FILL");
    p.c_frame_begin_large_setup = path("FRAME_BEGIN:large", "FILL");
    p.c_setup = path("FILL_RECT", "FILL");
    p.c_line_setup = path("DRAW_SPAN:line", "LINE");
    p.c_span_fill_setup = path("DRAW_SPAN:fill", "FILL");
    p.c_frame_end_setup = path("FRAME_END", "");
    p.c_zclear_setup = path("DEPTH_CLEAR", "FILL");
    const bool wide = p.depth_bits == 32;
    p.c_zspan_setup = path(wide ? "DEPTH_SPAN32" : "DEPTH_SPAN", "");
    p.c_zspan_outside = path("DEPTH_SPAN:outside", "");
    p.c_zspan_below = path("DEPTH_SPAN:below", "");
    p.c_zspan_empty = path("DEPTH_SPAN:empty", "");
    p.c_zspan_empty_cut = path("DEPTH_SPAN:emptycut", "");
    // a cut on the left: the set-up through zclip less the set-up without it
    p.c_zclip = path(wide ? "DEPTH_SPAN32:cut" : "DEPTH_SPAN:cut", "") - p.c_zspan_setup;
    p.c_zpass = path(wide ? "ZPIXEL32:nearer" : "ZPIXEL16:nearer", "");
    p.c_zfail = path(wide ? "ZPIXEL32:farther" : "ZPIXEL16:farther", "");
    // the loop's return, and its last pixel's jump not taken (DSJS: a state dearer than taken)
    p.c_zexit = path("ZSPAN_EXIT", "") + path(wide ? "ZPIXEL32:last" : "ZPIXEL16:last", "") -
                path(wide ? "ZPIXEL32:farther" : "ZPIXEL16:farther", "");
    p.c_face_setup = path("FACE", "");
    p.c_face_point = path("FACE:point", "");
    p.c_face_last = path("FACE:last", "");
    // a row: its set-up, and its edge loop's last jump not taken (DSJS: a state dearer)
    p.c_face_row = path("FACE:row", "") + path("FACE:lastedge", "") - path("FACE:edge", "");
    p.c_face_edge = path("FACE:edge", "");
    // a run: its set-up to the pixel loop, and after it the step to the next row
    p.c_face_span = path(wide ? "FACE:span32" : "FACE:span", "") + path("FACE:step", "");
    p.c_face_empty = path("FACE:empty", "");
    p.c_face_done = path("FACE:done", "");
    p.c_face_level = path("FACE:level", "");
    p.c_face_level_none = path("FACE:levelnone", "");
    p.c_face_far = path("FACE:far", "");
    p.c_face_far_none = path("FACE:farnone", "");
    p.c_face_bound = path("FACE:nearer", "") - p.c_face_edge;
    p.c_face_level_point = path("FACE:levelpoint", "") - p.c_face_point;
    p.depth_priced = true;
    // A word of the bus written whole is one write cycle; a partial word is read, modified
    // and written (one CAS, one W, no byte strobes: the pin list); so is a pixel narrower than
    // the bus drawn by LINE, one pixel a time.
    // With page mode a row's words after its first are page-mode cycles; the first's extra
    // is the row's. With a CAS per byte a pixel of 8 bits or more is written alone.
    const uint32_t page = p.page_mode_states ? p.page_mode_states + p.wait_states : 0;
    p.c_op = page ? page : m;
    p.c_row = p.row_states + (page ? m - page : 0);
    const bool whole_pixel = p.bpp >= p.bus_bits || (p.byte_strobes && p.bpp >= 8);
    p.c_op_partial = p.byte_strobes && p.bpp >= 8 ? p.c_op : 2 * m;
    p.c_line_pix = (whole_pixel ? m : 2 * m) + p.c_line_extra;
    // Each word the host writes through HSTDATA is a memory cycle of the GSP's bus, which
    // the host's request wins over the GSP's own (User's Guide §11.3).
    p.c_host_word = m;
    // DRAM refresh (a cycle every refresh_every_states, User's Guide §6) and the display's
    // memory-to-register transfers take the bus from the GSP.
    if (p.refresh_every_states != 0 && p.refresh_every_states < 4 * m)
        throw std::runtime_error(fmt::format(
            "a refresh every {} states leaves the GSP less than three memory cycles in four",
            p.refresh_every_states));
    p.stolen_share =
        (p.refresh_every_states ? static_cast<double>(m) / p.refresh_every_states : 0) +
        p.screen_transfers_per_s * m / p.f_cyc_hz;
    if (!(p.stolen_share < 0.5))
        throw std::runtime_error(fmt::format(
            "refresh and screen transfers would take {:.0f}% of the bus", 100 * p.stolen_share));
    // Host strobe to next strobe at least 7 tQ + 10 ns, tQ a quarter state (SPVS002C p. 34,
    // parameter 3); and each word waits for its memory cycle (HRDY).
    const double state_s = 1 / p.f_cyc_hz;
    const double word_s = std::max(7 * state_s / 4 + 10e-9, m * state_s);
    p.host_port_bytes_per_s =
        p.host_port_rated_bytes_per_s > 0 ? p.host_port_rated_bytes_per_s : 2 / word_s;
    p.outside_pays_setup = true;
}

nlohmann::json command_buffer_json(uint64_t bytes) {
    return bytes == kUnboundedBuffer ? json(kUnbounded) : json(bytes);
}

std::string command_buffer_text(uint64_t bytes) {
    return bytes == kUnboundedBuffer ? std::string(kUnbounded) : fmt::format("{} bytes", bytes);
}

std::string host_stall_text(uint64_t buffer_bytes, double stalled_ms) {
    return buffer_bytes == kUnboundedBuffer
               ? fmt::format("host waited for the bus {:.3f} ms", stalled_ms)
               : fmt::format("host stalled {:.3f} ms (bus or full buffer)", stalled_ms);
}

CostProfile band_end(const CostProfile& profile, bool dear) {
    CostProfile p = profile;
    p.name += dear ? " (dear end)" : " (cheap end)";
    for (const auto& [field, band] : profile.bands) {
        const Bandable& figure = *bandable(field);  // parse_profile admits no other
        if (field == "gsp") {
            p.listing_dear = dear;
            p.listing_cheap = !dear;
            continue;
        }
        const double v = dear == figure.more_is_dear ? band.high : band.low;
        if (figure.cycles)
            p.*figure.cycles = static_cast<uint32_t>(v);  // whole, at most kMaxCycleFigure
        else if (figure.real)
            p.*figure.real = v;
        else if (dear)  // the buffer: its band's high end is the figure itself
            p.command_buffer_bytes = static_cast<uint64_t>(band.low);
    }
    derive_figures(p);
    return p;
}

nlohmann::json CostProfile::to_json() const {
    json bands_json = json::object();
    for (const auto& [field, band] : bands) {
        if (field == "gsp") {
            bands_json[field] = {{"why", band.why}};
            continue;
        }
        bands_json[field] = {{"low", band.low}, {"why", band.why}};
        if (field != "command_buffer_bytes") bands_json[field]["high"] = band.high;
    }
    json bytes_json = json::object();
    for (protocol::Opcode op : protocol::kOpcodes)
        if (!protocol::is_depth_opcode(op))
            bytes_json[protocol::to_string(op)] = bytes[protocol::opcode_index(op)];
    json j{{"name", name},
           {"description", description},
           {"f_cyc_hz", f_cyc_hz},
           {"bpp", bpp},
           {"bus_bits", bus_bits},
           {"depth_bits", depth_bits},
           {"C_row", row_states},
           {"span_as", controller::to_string(span_as)},
           {"B_bus_bytes_per_s",
            std::isinf(b_bus_bytes_per_s) ? json(kUnlimited) : json(b_bus_bytes_per_s)},
           {"t_handshake_s", t_handshake_s},
           {"bytes", bytes_json},
           {"command_buffer_bytes", command_buffer_json(command_buffer_bytes)},
           {"sources", sources},
           {"bands", bands_json}};
    if (gsp.empty()) {
        j["C_cmd"] = c_cmd;
        j["C_setup"] = c_setup;
        j["C_op"] = c_op;
        j["C_line_setup"] = c_line_setup;
        j["C_line_pix"] = c_line_pix;
    } else {
        j["gsp"] = gsp;
        j["gsp_chip"] = std::string(chip_name(gsp_chip));
        j["memory_cycle_states"] = memory_cycle_states;
        j["wait_states"] = wait_states;
        j["refresh_every_states"] = refresh_every_states;
        j["screen_transfers_per_s"] = screen_transfers_per_s;
        j["C_line_extra"] = c_line_extra;
        j["byte_strobes"] = byte_strobes;
        j["page_mode_states"] = page_mode_states;
        j["clear_as"] = controller::to_string(clear_as);
        if (host_port_rated_bytes_per_s > 0)
            j["host_port_bytes_per_s"] = host_port_rated_bytes_per_s;
        // What the listing and the memory model come to; ignored when the file is read.
        j["derived"] = {{"C_cmd", c_cmd},
                        {"C_row", c_row},
                        {"C_setup", c_setup},
                        {"C_frame_begin_setup", c_frame_begin_setup},
                        {"C_frame_begin_srt_setup", c_frame_begin_srt_setup},
                        {"C_frame_begin_large_setup", c_frame_begin_large_setup},
                        {"C_tiga_call", c_tiga_call},
                        {"C_line_setup", c_line_setup},
                        {"C_span_fill_setup", c_span_fill_setup},
                        {"C_frame_end_setup", c_frame_end_setup},
                        {"C_op", c_op},
                        {"C_op_partial", c_op_partial},
                        {"C_line_pix", c_line_pix},
                        {"C_host_word", c_host_word},
                        {"stolen_share", stolen_share},
                        {"host_port_bytes_per_s", host_port_bytes_per_s},
                        {"C_zclear_setup", c_zclear_setup},
                        {"C_zspan_setup", c_zspan_setup},
                        {"C_zspan_outside", c_zspan_outside},
                        {"C_zspan_below", c_zspan_below},
                        {"C_zspan_empty", c_zspan_empty},
                        {"C_zspan_empty_cut", c_zspan_empty_cut},
                        {"C_zclip", c_zclip},
                        {"C_zpass", c_zpass},
                        {"C_zfail", c_zfail},
                        {"C_zexit", c_zexit},
                        {"C_face_setup", c_face_setup},
                        {"C_face_point", c_face_point},
                        {"C_face_last", c_face_last},
                        {"C_face_row", c_face_row},
                        {"C_face_edge", c_face_edge},
                        {"C_face_span", c_face_span},
                        {"C_face_empty", c_face_empty},
                        {"C_face_done", c_face_done},
                        {"C_face_level", c_face_level},
                        {"C_face_level_none", c_face_level_none},
                        {"C_face_far", c_face_far},
                        {"C_face_far_none", c_face_far_none},
                        {"C_face_bound", c_face_bound},
                        {"C_face_level_point", c_face_level_point}};
    }
    return j;
}

uint32_t CostProfile::largest_tiling_bytes() const {
    uint32_t largest = 0;
    for (protocol::Opcode op : protocol::kOpcodes)
        if (!protocol::is_depth_opcode(op)) largest = std::max(largest, bytes_of(op));
    return largest;
}

uint64_t CostProfile::depth_buffer_bytes(uint32_t width, uint32_t height) const {
    const uint64_t pitch_words = std::bit_ceil(uint64_t{width});
    return pitch_words * height * depth_bits / 8;
}

std::string CostProfile::to_string() const {
    const double bus_rate = bus_bytes_per_s();
    const std::string bus =
        std::isinf(bus_rate) ? std::string("unlimited") : fmt::format("{:g} MB/s", bus_rate / 1e6);
    const std::string model =
        gsp.empty() ? std::string("given figures")
                    : fmt::format("listing {}, memory cycle {}+{} states, {:.2f}% to refresh", gsp,
                                  memory_cycle_states, wait_states, 100 * stolen_share);
    return fmt::format(
        "{} ({:g} MHz, {} bpp on a {}-bit bus, {}: C_cmd {}, C_setup {}, C_op {}/{} partial, "
        "C_row {}, spans as {}, clear by {}, C_line_setup {}, C_line_pix {}, host word {}, bus "
        "{} + {:g} us/command)",
        name, f_cyc_hz / 1e6, bpp, bus_bits, model, c_cmd, c_setup, c_op, c_op_partial, c_row,
        controller::to_string(span_as), controller::to_string(clear_as), c_line_setup, c_line_pix,
        c_host_word, bus, t_handshake_s * 1e6);
}

std::vector<std::string> list_profiles() {
    std::vector<std::string> names;
    for (const BuiltinProfile& b : builtin_profiles())
        names.emplace_back(b.name);
    std::sort(names.begin(), names.end());
    return names;
}

CostProfile load_profile_file(const std::filesystem::path& path) {
    return parse_profile(read_text_file(path), path.string(), path.stem().string());
}

CostProfile load_profile(std::string_view name_or_path) {
    const bool looks_like_path =
        name_or_path.find('/') != std::string_view::npos || name_or_path.ends_with(".json");
    if (!looks_like_path) {
        for (const BuiltinProfile& b : builtin_profiles())
            if (b.name == name_or_path)
                return parse_profile(b.json, fmt::format("{}.json (built-in)", b.name), b.name);
    }
    const std::filesystem::path path{std::string(name_or_path)};
    if (looks_like_path || std::filesystem::exists(path)) return load_profile_file(path);
    throw std::runtime_error(fmt::format(
        "unknown profile \"{}\": the built-in profiles are {}; or give the path of a JSON file",
        name_or_path, fmt::join(list_profiles(), ", ")));
}

}  // namespace fb89::controller
