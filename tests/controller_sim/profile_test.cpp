// Tests of controller_sim/profile: the built-in profiles hold the design's figures, every
// figure carries its source, and a bad profile is refused with the file and field named.
#include "controller_sim/profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "controller_sim/cost_model.h"
#include "tests/scratch.h"

namespace fb89::controller {
namespace {

using nlohmann::json;
using protocol::Opcode;

// A profile that gives its cycle figures (the first model's, tms34010-mame) without its
// bands, so that a test may set any figure anywhere (with a band, a figure outside it is
// refused: Profile.BandsHoldTheirFiguresAndSayWhy).
json default_profile_json() {
    json j = load_profile("tms34010-mame").to_json();
    j.erase("bands");
    return j;
}
// The default profile (a listing and a memory model), bands and all.
json listing_profile_json() {
    return load_profile("tms34010-50mhz").to_json();
}

// The message parse_profile throws for `j`, or "" when it loads.
std::string load_error(const json& j) {
    try {
        parse_profile(j.dump(), "bad.json");
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

TEST(Profile, DefaultIsTms34010At50MhzPricedFromTheDataSheet) {
    const CostProfile p = default_profile();
    EXPECT_EQ(p.name, "tms34010-50mhz");
    EXPECT_EQ(p.f_cyc_hz, 50.35e6 / 8);  // TI's development board's INCLK, TDB10/README.1ST
    EXPECT_EQ(p.bpp, 8u);
    EXPECT_EQ(p.bus_bits, 16u);
    EXPECT_EQ(p.pixels_per_word(), 2u);
    EXPECT_EQ(p.gsp, "tms34010");
    EXPECT_EQ(p.memory_cycle_states, 2u);
    EXPECT_EQ(p.wait_states, 0u);
    EXPECT_EQ(p.refresh_every_states, 64u);
    EXPECT_EQ(p.screen_transfers_per_s, 46'800);
    // derived: the listing's paths and the memory cycles
    EXPECT_EQ(p.c_cmd, 21u);
    EXPECT_EQ(p.c_setup, 35u);
    EXPECT_EQ(p.c_line_setup, 39u);
    EXPECT_EQ(p.c_op, 2u);
    EXPECT_EQ(p.c_op_partial, 4u);
    EXPECT_EQ(p.c_row, 1u);  // TI's simulator's state a FILL row
    EXPECT_EQ(p.c_line_pix, 4u);
    EXPECT_EQ(p.c_host_word, 2u);
    EXPECT_TRUE(p.outside_pays_setup);
    EXPECT_EQ(p.span_as, SpanAs::Fill);              // TI's draw_line
    EXPECT_EQ(p.clear_as, ClearAs::SerialRegister);  // TI's clear_page
    EXPECT_EQ(p.c_span_fill_setup, 40u);
    EXPECT_EQ(p.c_frame_begin_srt_setup, 116u);
    EXPECT_EQ(p.c_tiga_call, 145u);
    EXPECT_EQ(p.b_bus_bytes_per_s, 8e6);
    EXPECT_EQ(p.bus_bytes_per_s(), 2 / (2 * 8 / 50.35e6));  // a word a memory cycle
    EXPECT_EQ(p.t_handshake_s, 1e-6);
    EXPECT_EQ(p.bytes_of(Opcode::FillRect), 12u);
    EXPECT_EQ(p.bytes_of(Opcode::DrawSpan), 10u);
    EXPECT_EQ(p.bytes_of(Opcode::FrameBegin), 10u);
    EXPECT_EQ(p.bytes_of(Opcode::FrameEnd), 2u);
    EXPECT_EQ(p.bytes_of(Opcode::Marker), 0u);
}

TEST(Profile, TheFirstModelKeepsItsGivenFigures) {
    const CostProfile p = load_profile("tms34010-mame");
    EXPECT_TRUE(p.gsp.empty());
    EXPECT_EQ(p.c_cmd, 25u);
    EXPECT_EQ(p.c_setup, 8u);
    EXPECT_EQ(p.c_op, 2u);
    EXPECT_EQ(p.c_op_partial, 2u);
    EXPECT_EQ(p.c_line_setup, 12u);
    EXPECT_EQ(p.c_line_pix, 2u);
    EXPECT_EQ(p.c_host_word, 0u);
    EXPECT_EQ(p.stolen_share, 0.0);
    EXPECT_FALSE(p.outside_pays_setup);
    EXPECT_EQ(p.bus_bytes_per_s(), 8e6);
}

TEST(Profile, Tms34020HasAHundredNanosecondStatePageModeAndByteStrobes) {
    const CostProfile p = load_profile("tms34020-40mhz");
    EXPECT_EQ(p.f_cyc_hz, 10e6);
    EXPECT_EQ(p.bus_bits, 32u);
    EXPECT_EQ(p.b_bus_bytes_per_s, 20e6);
    EXPECT_TRUE(p.byte_strobes);
    EXPECT_EQ(p.page_mode_states, 1u);
    EXPECT_EQ(p.bus_bytes_per_s(), 20e6);  // the port as SPVS004D rates it
}

TEST(Profile, ListsTheBuiltInProfiles) {
    EXPECT_EQ(list_profiles(), (std::vector<std::string>{"ideal", "tms34010-50mhz", "tms34010-isa",
                                                         "tms34010-mame", "tms34020-40mhz"}));
}

TEST(Profile, EveryBuiltInFigureCitesItsSource) {
    for (const std::string& name : list_profiles()) {
        const CostProfile p = load_profile(name);
        for (const auto& [field, source] : p.sources)
            EXPECT_TRUE(source.rfind("[DS]", 0) == 0 || source.rfind("[UG]", 0) == 0 ||
                        source.rfind("[UG20]", 0) == 0 || source.rfind("[EMU]", 0) == 0 ||
                        source.rfind("[EST]", 0) == 0 || source.rfind("[TI]", 0) == 0 ||
                        source.rfind("[SIM]", 0) == 0)
                << name << " " << field << ": " << source;
        if (name == "ideal") continue;
        std::vector<const char*> fields = {
            "f_cyc_hz",          "bpp",           "C_row", "span_as",
            "B_bus_bytes_per_s", "t_handshake_s", "bytes", "command_buffer_bytes"};
        if (p.gsp.empty())
            fields.insert(fields.end(), {"C_cmd", "C_setup", "C_op", "C_line_setup", "C_line_pix"});
        else
            fields.insert(fields.end(), {"bus_bits", "gsp", "memory_cycle_states", "wait_states",
                                         "refresh_every_states", "screen_transfers_per_s",
                                         "C_line_extra", "clear_as"});
        for (const char* field : fields)
            EXPECT_TRUE(p.sources.contains(field)) << name << " has no source for " << field;
    }
}

// A profile with a listing gives its memory model and never the figures derived from it.
TEST(Profile, AListingProfileDerivesItsCycleFiguresAndRefusesThemGiven) {
    json j = listing_profile_json();
    j["C_cmd"] = 25;
    EXPECT_NE(load_error(j).find("\"C_cmd\": derived from the listing"), std::string::npos)
        << load_error(j);
    j = listing_profile_json();
    j.erase("wait_states");
    EXPECT_NE(load_error(j).find("\"wait_states\": missing"), std::string::npos) << load_error(j);
    j = listing_profile_json();
    j["gsp"] = "tms9918";
    EXPECT_NE(load_error(j).find("\"gsp\": unknown GSP listing \"tms9918\""), std::string::npos)
        << load_error(j);
    j = default_profile_json();
    j["wait_states"] = 1;
    EXPECT_NE(load_error(j).find("\"wait_states\": only a profile with \"gsp\""), std::string::npos)
        << load_error(j);
    j = listing_profile_json();
    j["bpp"] = 16;
    j["bus_bits"] = 8;
    EXPECT_NE(load_error(j).find("\"bus_bits\": must be 16 or 32"), std::string::npos);
    j = listing_profile_json();
    j["bands"].erase("refresh_every_states");
    j["refresh_every_states"] = 4;
    EXPECT_NE(load_error(j).find("\"refresh_every_states\": 0 (no refresh) or at least"),
              std::string::npos)
        << load_error(j);
    j = listing_profile_json();
    j["page_mode_states"] = 3;
    EXPECT_NE(load_error(j).find("\"page_mode_states\": a page-mode cycle is no longer"),
              std::string::npos)
        << load_error(j);
    j = listing_profile_json();
    j["byte_strobes"] = "yes";
    EXPECT_NE(load_error(j).find("\"byte_strobes\": expected true or false"), std::string::npos);
    j = default_profile_json();
    j["page_mode_states"] = 1;
    EXPECT_NE(load_error(j).find("\"page_mode_states\": only a profile with \"gsp\""),
              std::string::npos)
        << load_error(j);
    j = listing_profile_json();
    j["gsp_chip"] = "tms34030";
    EXPECT_NE(load_error(j).find("\"gsp_chip\": expected \"tms34010\" or \"tms34020\""),
              std::string::npos)
        << load_error(j);
    j["gsp_chip"] = "tms34020";
    EXPECT_EQ(parse_profile(j.dump(), "test").gsp_chip, Chip::Tms34020);
    j = default_profile_json();
    j["gsp_chip"] = "tms34020";
    EXPECT_NE(load_error(j).find("\"gsp_chip\": only a profile with \"gsp\""), std::string::npos)
        << load_error(j);
    // "derived" is written for the reader and ignored when read
    j = listing_profile_json();
    j["derived"]["C_cmd"] = 1;
    EXPECT_EQ(parse_profile(j.dump(), "test").c_cmd, 21u);
}

TEST(Profile, TheCommandBufferIsUnboundedOrHoldsTheLargestCommand) {
    EXPECT_EQ(default_profile().command_buffer_bytes, kUnboundedBuffer);
    json j = default_profile_json();
    j.erase("command_buffer_bytes");
    EXPECT_EQ(parse_profile(j.dump(), "absent").command_buffer_bytes, kUnboundedBuffer);
    j["command_buffer_bytes"] = 4096;
    EXPECT_EQ(parse_profile(j.dump(), "4 KB").command_buffer_bytes, 4096u);
    EXPECT_EQ(parse_profile(j.dump(), "4 KB").to_json()["command_buffer_bytes"], 4096);
    for (const json& bad : {json(11), json(-1), json(1.5), json("lots")}) {  // FILL_RECT is 12
        j["command_buffer_bytes"] = bad;
        try {
            parse_profile(j.dump(), "bad");
            ADD_FAILURE() << bad.dump();
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("command_buffer_bytes"), std::string::npos)
                << e.what();
        }
    }
}

// Bands: every built-in profile's estimates have one, with the figure inside it; the two
// ends bound the controller's time on a frame; a band without its reason, outside its
// figure or on a figure that cannot have one is refused, naming it.
TEST(Profile, BandsHoldTheirFiguresAndSayWhy) {
    for (const char* name : {"tms34010-50mhz", "tms34010-isa", "tms34020-40mhz"}) {
        const CostProfile p = load_profile(name);
        for (const char* field :
             {"gsp", "wait_states", "refresh_every_states", "screen_transfers_per_s", "C_row",
              "C_line_extra", "B_bus_bytes_per_s", "t_handshake_s", "command_buffer_bytes"})
            EXPECT_TRUE(p.bands.count(field)) << name << " " << field;
        const CostProfile cheap = band_end(p, false), dear = band_end(p, true);
        EXPECT_LE(cheap.c_cmd, p.c_cmd);
        EXPECT_GE(dear.c_cmd, p.c_cmd);
        EXPECT_LE(cheap.c_line_setup, p.c_line_setup);
        EXPECT_GE(dear.c_line_pix, p.c_line_pix);
        EXPECT_GE(dear.stolen_share, p.stolen_share);
        EXPECT_LE(cheap.stolen_share, p.stolen_share);
        EXPECT_GE(cheap.bus_bytes_per_s(), p.bus_bytes_per_s());
        EXPECT_LE(dear.bus_bytes_per_s(), p.bus_bytes_per_s());
        EXPECT_EQ(dear.command_buffer_bytes, 1024u);
        EXPECT_EQ(cheap.command_buffer_bytes, p.command_buffer_bytes);
        EXPECT_EQ(dear.name, std::string(name) + " (dear end)");
    }
    const CostProfile p = load_profile("tms34010-50mhz");
    const CostProfile dear = band_end(p, true);
    EXPECT_EQ(dear.wait_states, 1u);
    EXPECT_EQ(dear.refresh_every_states, 32u);
    EXPECT_EQ(dear.c_op, 3u);
    EXPECT_EQ(dear.c_line_pix, 2u * 3u + 2u);
    // wait states on its reads (GSPSIM's states, as the estimate); and TIGA's call around it
    EXPECT_EQ(dear.c_cmd, 21u + 3u + 195u);
    // the lean executive, each memory MOVE a state to issue and its cycles
    EXPECT_EQ(band_end(p, false).c_cmd, 18u);
    EXPECT_EQ(dear.b_bus_bytes_per_s, 4e6);
    EXPECT_EQ(dear.t_handshake_s, 3e-6);
    EXPECT_EQ(band_end(p, false).c_line_setup, 31u);  // the same; LINE's own set-up at 2
    // the first model's bands are on its given figures
    const CostProfile first = load_profile("tms34010-mame");
    EXPECT_EQ(band_end(first, true).c_cmd, 50u);
    EXPECT_EQ(band_end(first, false).c_cmd, 12u);
    // a band needs its reason, must hold its figure and may only be on a banded figure
    json j = load_profile("tms34010-mame").to_json();
    j["bands"]["C_cmd"].erase("why");
    EXPECT_NE(load_error(j).find("\"bands.C_cmd.why\": missing"), std::string::npos)
        << load_error(j);
    j = load_profile("tms34010-mame").to_json();
    j["C_cmd"] = 60;
    EXPECT_NE(load_error(j).find("\"bands.C_cmd\": the figure 60 must lie within its band"),
              std::string::npos)
        << load_error(j);
    j = listing_profile_json();
    j["bands"]["bpp"] = {{"low", 4}, {"high", 16}, {"why", "x"}};
    EXPECT_NE(load_error(j).find("\"bands.bpp\": names no figure that can have a band"),
              std::string::npos)
        << load_error(j);
    j = listing_profile_json();
    j["bands"]["C_cmd"] = {{"low", 4}, {"high", 60}, {"why", "x"}};
    EXPECT_NE(load_error(j).find("\"bands.C_cmd\": a figure derived from the listing"),
              std::string::npos)
        << load_error(j);
    j = listing_profile_json();
    j["bands"]["command_buffer_bytes"]["low"] = 8;  // FILL_RECT takes 12
    EXPECT_NE(load_error(j).find("\"bands.command_buffer_bytes.low\""), std::string::npos)
        << load_error(j);
}

TEST(Profile, ToJsonLoadsBackToTheSameProfile) {
    for (const std::string& name : list_profiles()) {
        const CostProfile p = load_profile(name);
        const CostProfile q = parse_profile(p.to_json().dump(), "round trip");
        EXPECT_EQ(q.to_json(), p.to_json()) << name;
    }
}

TEST(Profile, LoadsUserFileByPathWithCommentsAndNameFromStem) {
    json j = default_profile_json();
    j.erase("name");
    j["C_cmd"] = 40;
    const auto path = fb89::testing::scratch_path("profile_test_mine.json");
    std::ofstream(path) << "// a user profile\n" << j.dump(2) << "\n/* trailing comment */\n";
    const CostProfile p = load_profile(path.string());
    std::filesystem::remove(path);
    EXPECT_EQ(p.name, path.stem().string());
    EXPECT_EQ(p.c_cmd, 40u);
}

TEST(Profile, MissingFieldErrorNamesFileAndField) {
    json j = default_profile_json();
    j.erase("C_op");
    const std::string e = load_error(j);
    EXPECT_NE(e.find("bad.json"), std::string::npos) << e;
    EXPECT_NE(e.find("\"C_op\""), std::string::npos) << e;
    EXPECT_NE(e.find("missing"), std::string::npos) << e;
}

TEST(Profile, WrongTypeErrorNamesField) {
    json j = default_profile_json();
    j["C_setup"] = "eight";
    EXPECT_NE(load_error(j).find("\"C_setup\": expected an integer"), std::string::npos);
    j = default_profile_json();
    j["C_setup"] = 8.5;
    EXPECT_NE(load_error(j).find("\"C_setup\": expected an integer"), std::string::npos);
    j = default_profile_json();
    j["f_cyc_hz"] = "fast";
    EXPECT_NE(load_error(j).find("\"f_cyc_hz\": expected a number"), std::string::npos);
    j = default_profile_json();
    j["span_as"] = "dots";
    EXPECT_NE(load_error(j).find("\"span_as\""), std::string::npos);
}

TEST(Profile, NegativeValueErrorNamesField) {
    json j = default_profile_json();
    j["C_op"] = -2;
    EXPECT_NE(load_error(j).find("\"C_op\": must not be negative"), std::string::npos);
    j = default_profile_json();
    j["t_handshake_s"] = -1e-6;
    EXPECT_NE(load_error(j).find("\"t_handshake_s\": must not be negative"), std::string::npos);
    j = default_profile_json();
    j["B_bus_bytes_per_s"] = 0;
    EXPECT_NE(load_error(j).find("\"B_bus_bytes_per_s\": must be greater than zero"),
              std::string::npos);
}

// Rates no machine has would make every modelled time infinite (or zero): refused, named.
TEST(Profile, RatesOutsideAnyMachinesAreRefused) {
    for (const char* field : {"f_cyc_hz", "B_bus_bytes_per_s"})
        for (double value : {1e-300, 0.5, 2e12, 1e300}) {
            json j = default_profile_json();
            j[field] = value;
            EXPECT_NE(
                load_error(j).find(std::string("\"") + field + "\": must be between 1 and 1e+12"),
                std::string::npos)
                << field << " " << value;
        }
    json j = default_profile_json();
    j["t_handshake_s"] = 1e-300;
    EXPECT_NE(load_error(j).find("\"t_handshake_s\": must be 0 or between 1e-15 and 1"),
              std::string::npos);
    j["t_handshake_s"] = 2;
    EXPECT_NE(load_error(j).find("\"t_handshake_s\": must be 0 or between"), std::string::npos);
    for (double fine : {0.0, 1e-9, 1.0}) {
        j["t_handshake_s"] = fine;
        EXPECT_NO_THROW(parse_profile(j.dump(), "test")) << fine;
    }
    j["f_cyc_hz"] = 1;
    j["B_bus_bytes_per_s"] = 1e12;
    const CostProfile p = parse_profile(j.dump(), "test");
    EXPECT_TRUE(std::isfinite(bus_seconds(p, 1'000'000)));
}

TEST(Profile, UnlimitedBusTakesNoTimeAndRoundTrips) {
    json j = default_profile_json();
    j["B_bus_bytes_per_s"] = "unlimited";
    const CostProfile p = parse_profile(j.dump(), "test");
    EXPECT_TRUE(std::isinf(p.b_bus_bytes_per_s));
    EXPECT_EQ(bus_seconds(p, 12), p.t_handshake_s);
    EXPECT_NE(p.to_string().find("bus unlimited"), std::string::npos);
    EXPECT_EQ(p.to_json()["B_bus_bytes_per_s"], "unlimited");
    EXPECT_TRUE(std::isinf(parse_profile(p.to_json().dump(), "again").b_bus_bytes_per_s));
    j["B_bus_bytes_per_s"] = "fast";
    EXPECT_NE(load_error(j).find("\"B_bus_bytes_per_s\": expected a number or \"unlimited\""),
              std::string::npos);
}

TEST(Profile, BadBppAndOpcodeBytesAreNamed) {
    json j = default_profile_json();
    j["bpp"] = 3;
    EXPECT_NE(load_error(j).find("\"bpp\": must be 1, 2, 4, 8 or 16"), std::string::npos);
    j = default_profile_json();
    j["bytes"]["DRAW_SPAN"] = 14;
    EXPECT_EQ(parse_profile(j.dump(), "wider").bytes_of(protocol::Opcode::DrawSpan), 14u);
    j["bytes"].erase("DRAW_SPAN");  // not given: its words on the host port, from its row
    EXPECT_EQ(parse_profile(j.dump(), "rows").bytes_of(protocol::Opcode::DrawSpan), 10u);
    j = default_profile_json();
    j["bytes"]["FILL_RECT"] = -12;
    EXPECT_NE(load_error(j).find("\"bytes.FILL_RECT\": must not be negative"), std::string::npos);
}

TEST(Profile, UnknownFieldIsAnErrorNotASilentDefault) {
    json j = default_profile_json();
    j["C_ops"] = 2;
    EXPECT_NE(load_error(j).find("\"C_ops\": unknown field"), std::string::npos);
}

TEST(Profile, InvalidJsonErrorNamesFile) {
    try {
        parse_profile("{ \"C_op\": ", "broken.json");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("broken.json: not valid JSON"), std::string::npos);
    }
}

TEST(Profile, UnknownNameListsBuiltInsAndMissingFileNamesPath) {
    try {
        load_profile("tms9918");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("tms34010-50mhz"), std::string::npos) << e.what();
    }
    try {
        load_profile("/nonexistent/dir/p.json");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/p.json"), std::string::npos);
    }
}

}  // namespace
}  // namespace fb89::controller
