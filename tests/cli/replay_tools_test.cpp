// `fb89 replay`, `dump`, `info`, `trim` and `diff` as a user runs them: on streams recorded
// by `fb89 render` and on small ones built here with the protocol's encoder, including
// truncated and corrupt ones (every tool reports them and exits 2, never crashes).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "controller_sim/png_io.h"
#include "protocol/stream_reader.h"
#include "protocol/stream_writer.h"
#include "tests/cli/bad_input.h"
#include "tests/cli/cli_runner.h"
#include "tests/scenes_dir.h"

namespace {

namespace fs = std::filesystem;
namespace pr = fb89::protocol;

using fb89::testing::CliRun;
using fb89::testing::run_fb89;
using fb89::testing::slurp;
using fb89::testing::test_dir;
using fb89::testing::bad_input::scratch;

using fb89::testing::kScenes;

// Three 8x6 frames; frame 1 has a fill at command 6, frame 2 a span and a marker.
std::vector<pr::Command> three_frames() {
    return {
        pr::FrameBegin{0, 8, 6, pr::Rgb{0, 0, 0}},
        pr::Marker{"warnock"},
        pr::FillRect{0, 0, 4, 4, pr::Rgb{255, 0, 0}},
        pr::DrawSpan{5, 1, 6, pr::Rgb{0, 255, 0}},
        pr::FrameEnd{},
        pr::FrameBegin{1, 8, 6, pr::Rgb{0, 0, 64}},
        pr::FillRect{2, 2, 3, 3, pr::Rgb{9, 9, 9}},
        pr::FrameEnd{},
        pr::FrameBegin{2, 8, 6, pr::Rgb{10, 20, 30}},
        pr::DrawSpan{0, 0, 7, pr::Rgb{0, 0, 255}},
        pr::Marker{"done"},
        pr::FrameEnd{},
    };
}

// Cutting this many bytes off three_frames()'s stream in format version 1 ends it inside
// frame 2's span: the index (85 bytes), FRAME_END (1) and MARKER "done" (7) go, and 2 bytes
// of the span. (Version 4 reads a batch whole: cut there, it delivers none of frame 2's
// batch; stream_checksum_test.cpp.)
constexpr std::size_t kCutInFrame2 = 95;

std::string write_stream(const std::string& name, const std::vector<pr::Command>& commands,
                         std::size_t cut_to = 0, pr::Checksums checksums = pr::Checksums::On) {
    std::vector<uint8_t> bytes = pr::encode_stream(commands, {{"scene", "built"}}, true, checksums);
    if (cut_to) bytes.resize(cut_to);
    const std::string path = scratch(name);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    return path;
}

// Records scenes/A.json at 256x195 with the Z-buffer (with its send times, in version 4).
std::string record_a(const std::string& name = "a.fb89", const std::string& extra = "") {
    const std::string path = scratch(name);
    CliRun r =
        run_fb89("render " + kScenes + "/A.json --size 256x195 -q --stream " + path + " " + extra);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return path;
}

nlohmann::json replay_stats(const std::string& stream, const std::string& extra = "") {
    const std::string stats = scratch("replay_stats.json");
    CliRun r = run_fb89("replay " + stream + " -q --stats " + stats + " " + extra);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(slurp(stats));
}

std::vector<std::string> complete_lines(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (std::size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1)
        out.push_back(text.substr(start, nl - start));
    return out;
}

TEST(ReplayCommand, ReplaysUnderAnotherProfileWithTheRendersChecksum) {
    const std::string stream = scratch("a.fb89"), render_stats = scratch("render.json");
    ASSERT_EQ(run_fb89("render " + kScenes + "/A.json --size 256x195 -q --stream " + stream +
                       " --stats " + render_stats)
                  .exit_code,
              0);
    const auto rendered = nlohmann::json::parse(slurp(render_stats));
    const auto slow = replay_stats(stream, "--profile tms34010-50mhz");
    const auto ideal = replay_stats(stream, "--profile ideal");
    EXPECT_EQ(slow["controller"]["frames"][0]["checksum"],
              rendered["controller"]["frames"][0]["checksum"]);
    EXPECT_EQ(ideal["controller"]["frames"][0]["checksum"],
              rendered["controller"]["frames"][0]["checksum"]);
    EXPECT_EQ(slow["controller"]["totals"]["all"]["cycles"],
              rendered["controller"]["totals"]["all"]["cycles"]);
    EXPECT_EQ(ideal["controller"]["totals"]["all"]["cycles"], 0);
    CliRun text = run_fb89("replay " + stream + " --profile tms34020-40mhz");
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("profile tms34020-40mhz"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("checksum"), std::string::npos) << text.out;
}

// --buffer and --timeline: each frame through the pipeline in time, every command ready at 0
// (a version-1 stream has no send times, and the line says so); a buffer smaller than the
// largest command is a usage error, and a timeline that cannot be written leaves nothing.
TEST(ReplayCommand, TheBufferAndTheTimelineRunTheStreamsFramesThroughThePipeline) {
    const std::string stream = record_a("a_untimed.fb89", "--untimed-stream"),
                      timeline = scratch("replay_timeline.json");
    CliRun r = run_fb89("replay " + stream + " --buffer 64 --timeline " + timeline);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("pipeline, frame 0 (no send times in the stream: every command ready at "
                         "0; buffer 64 bytes): frame "),
              std::string::npos)
        << r.out;
    const nlohmann::json t = nlohmann::json::parse(slurp(timeline));
    EXPECT_EQ(t["otherData"]["send_times"], "none: every command ready at 0");
    EXPECT_EQ(t["otherData"]["buffer_bytes"], 64);
    EXPECT_LE(t["otherData"]["buffer_high_water_bytes"].get<uint64_t>(), 64u);
    double controller_us = 0;
    for (const auto& e : t["traceEvents"])
        if (e["ph"] == "X" && e["tid"] == 3) controller_us += e["dur"].get<double>();
    EXPECT_NEAR(controller_us, t["otherData"]["controller_busy_ms"].get<double>() * 1e3,
                1e-6 * controller_us);
    r = run_fb89("replay " + stream + " --buffer 5");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--buffer: 5 bytes cannot hold a command"), std::string::npos) << r.err;
    const std::string blocked = scratch("not-a-folder");
    { std::ofstream(blocked) << "x"; }
    r = run_fb89("replay " + stream + " -q --timeline " + blocked + "/t.json");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("not-a-folder"), std::string::npos) << r.err;
}

TEST(ReplayCommand, PngOfTheLastFrameEqualsTheRendersImage) {
    const std::string stream = scratch("a.fb89"), rendered = scratch("r.png"),
                      replayed = scratch("p.png");
    ASSERT_EQ(run_fb89("render " + kScenes + "/A.json --size 256x195 -q --stream " + stream +
                       " --png " + rendered)
                  .exit_code,
              0);
    ASSERT_EQ(run_fb89("replay " + stream + " -q --png " + replayed).exit_code, 0);
    EXPECT_EQ(fb89::controller::read_png(rendered).pixels,
              fb89::controller::read_png(replayed).pixels);
}

TEST(ReplayCommand, SnapshotsAreNamedWithTheCallNumber) {
    const std::string stream = write_stream("three.fb89", three_frames());
    CliRun r =
        run_fb89("replay " + stream + " -q --png " + scratch("out.png") + " --snapshot frame,2");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* name :
         {"out-000002.png", "out-000004.png", "out-000007.png", "out-000011.png"})
        EXPECT_TRUE(fs::exists(scratch(name))) << name;
    EXPECT_FALSE(fs::exists(scratch("out.png")));
    // right after call 2 only the red fill is drawn; the span of call 3 is not yet there
    const auto snap = fb89::controller::read_png(scratch("out-000002.png"));
    EXPECT_EQ(snap.pixels[0], 255);
    EXPECT_EQ(snap.pixels[(5 * 8 + 1) * 3 + 1], 0);
    EXPECT_EQ(run_fb89("replay " + stream + " --snapshot frame").exit_code, 2);
}

TEST(ReplayCommand, BenchmarkReportsThroughput) {
    const std::string stream = record_a();
    CliRun r = run_fb89("replay " + stream + " --benchmark");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("M commands/s"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Mpixels/s"), std::string::npos) << r.out;
    const auto j = replay_stats(stream, "--benchmark");
    EXPECT_GT(j["benchmark"]["commands"].get<uint64_t>(), 100u);
}

TEST(ReplayCommand, TruncatedStreamExitsTwoWritingNothingAndSalvageKeepsCompleteFrames) {
    const auto full =
        pr::encode_stream(three_frames(), {{"scene", "built"}}, true, pr::Checksums::Off);
    const std::string stream =
        write_stream("cut.fb89", three_frames(), full.size() - kCutInFrame2, pr::Checksums::Off);
    const std::string png = scratch("last.png"), stats = scratch("cut.json");
    CliRun r = run_fb89("replay " + stream + " --png " + png + " --stats " + stats);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("cut.fb89: truncated"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("at byte"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("(command "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("no output written (--salvage"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(png));
    EXPECT_FALSE(std::filesystem::exists(stats));
    // with --salvage: exit 0, a warning, and what the complete frames give
    r = run_fb89("replay --salvage " + stream + " --png " + png + " --stats " + stats);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("fb89: warning: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("kept the 2 complete frame(s)"), std::string::npos) << r.err;
    const auto j = nlohmann::json::parse(slurp(stats));
    EXPECT_EQ(j["controller"]["frames_closed"], 2);
    EXPECT_TRUE(j.contains("error"));
    // the PNG is frame 1's: background #000040 with a grey fill
    const auto image = fb89::controller::read_png(png);
    EXPECT_EQ(image.pixels[2], 64);
    EXPECT_EQ(image.pixels[(2 * 8 + 2) * 3], 9);
}

// The number after `label` in `text` (e.g. "frame " -> 12.345), or -1.
double value_after(const std::string& text, const std::string& label) {
    const std::size_t at = text.find(label);
    return at == std::string::npos ? -1 : std::stod(text.substr(at + label.size()));
}

TEST(ReplayCommand, ATimedStreamGoesThroughThePipelineAtItsSendTimesAsRendered) {
    const std::string stream = scratch("timed.fb89"), timeline = scratch("timed_timeline.json");
    CliRun render = run_fb89("render " + kScenes + "/A.json --size 256x195 --method scanline " +
                             "--buffer 2048 --stream " + stream);
    ASSERT_EQ(render.exit_code, 0) << render.err;
    CliRun r = run_fb89("replay " + stream + " --buffer 2048 --timeline " + timeline);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("format version 4"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("pipeline, frame 0 (send times from the stream, measured on native; "
                         "buffer 2048 bytes): frame "),
              std::string::npos)
        << r.out;
    // the render's frame and stalls, to the printed microsecond, without the host
    const double frame_ms = value_after(render.out, "buffer 2048 bytes): frame ");
    EXPECT_GT(frame_ms, 0) << render.out;
    EXPECT_EQ(value_after(r.out, "buffer 2048 bytes): frame "), frame_ms) << r.out;
    EXPECT_EQ(value_after(r.out, "host stalled "), value_after(render.out, "host stalled "));
    const nlohmann::json t = nlohmann::json::parse(slurp(timeline));
    EXPECT_EQ(t["otherData"]["send_times"], "measured on native");
    EXPECT_NEAR(t["otherData"]["frame_ms"].get<double>(), frame_ms, 0.0005);
}

TEST(StreamTools, InfoDumpTrimAndDiffShowAndKeepTheSendTimes) {
    const std::string stream = record_a("timed_a.fb89"), trimmed = scratch("timed_trim.fb89");
    CliRun info = run_fb89("info " + stream + " --json");
    ASSERT_EQ(info.exit_code, 0) << info.err;
    const nlohmann::json j = nlohmann::json::parse(info.out);
    EXPECT_EQ(j["version"], 4);
    EXPECT_EQ(j["send_times"], "measured on native");
    const double host_end_us = j["frames"][0]["host_end_us"].get<double>();
    EXPECT_GT(host_end_us, 0);
    EXPECT_GE(host_end_us, j["frames"][0]["last_send_us"].get<double>());
    info = run_fb89("info " + stream);
    EXPECT_NE(info.out.find("send times     measured on native"), std::string::npos) << info.out;

    CliRun dump = run_fb89("dump " + stream);
    ASSERT_EQ(dump.exit_code, 0) << dump.err;
    const auto lines = complete_lines(dump.out);
    ASSERT_GT(lines.size(), 2u);
    EXPECT_NE(lines.front().find("FRAME_BEGIN"), std::string::npos);
    EXPECT_NE(lines.front().find("  sent 0.000 us"), std::string::npos) << lines.front();
    EXPECT_NE(lines.back().find("FRAME_END  sent "), std::string::npos) << lines.back();
    EXPECT_NE(lines.back().find(", host end "), std::string::npos) << lines.back();

    // a frame kept whole keeps every command's time: the same dump, line for line, but for
    // the byte offsets (the trimmed stream's header says where it came from)
    ASSERT_EQ(run_fb89("trim " + stream + " --frames 0 -q -o " + trimmed).exit_code, 0);
    const std::regex offset(" @[0-9]+ +");
    EXPECT_TRUE(std::regex_replace(run_fb89("dump " + trimmed).out, offset, " ") ==
                std::regex_replace(dump.out, offset, " "));
    CliRun diff = run_fb89("diff " + stream + " " + trimmed);
    EXPECT_EQ(diff.exit_code, 0) << diff.out << diff.err;
    EXPECT_NE(diff.out.find("host end A ms"), std::string::npos) << diff.out;
    const std::string end_ms = fmt::format("{:.3f}", host_end_us / 1e3);
    EXPECT_NE(diff.out.find(end_ms + " " + std::string(14 - end_ms.size(), ' ') + end_ms),
              std::string::npos)
        << diff.out;
}

TEST(StreamTools, ATimeThatGoesBackIsRefusedNamingItsByteAndCommand) {
    std::vector<uint8_t> bytes;
    pr::encode_header(bytes, {}, pr::kTimedVersion);
    pr::encode_command(bytes, pr::FrameBegin{0, 8, 6, pr::Rgb{}});
    pr::encode_time(bytes, pr::kSendTimeOpcode, 2000);
    pr::encode_command(bytes, pr::FillRect{0, 0, 2, 2, pr::Rgb{}});
    pr::encode_time(bytes, pr::kSendTimeOpcode, 1000);  // byte 57
    pr::encode_command(bytes, pr::FrameEnd{});
    const std::string path = scratch("back.fb89");
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    for (const std::string tool : {"replay", "dump", "info"}) {
        CliRun r = run_fb89(tool + " " + path + (tool == "replay" ? " --buffer unbounded" : ""));
        EXPECT_EQ(r.exit_code, 2) << tool;
        EXPECT_NE(r.err.find("back.fb89: SEND_TIME at byte 57 (command 2): 1000 ns goes back "
                             "from the frame's send time 2000 ns"),
                  std::string::npos)
            << tool << ": " << r.err;
    }
}

// A frame that never ended has no host end: info says so rather than print a time.
TEST(InfoCommand, AFrameThatNeverEndedHasNoHostEnd) {
    std::vector<uint8_t> bytes;
    pr::encode_header(bytes, {}, pr::kTimedVersion);
    pr::encode_command(bytes, pr::FrameBegin{0, 8, 6, pr::Rgb{}});
    pr::encode_time(bytes, pr::kSendTimeOpcode, 1000);
    pr::encode_command(bytes, pr::FillRect{0, 0, 2, 2, pr::Rgb{}});
    pr::encode_time(bytes, pr::kHostEndOpcode, 3000);
    pr::encode_command(bytes, pr::FrameEnd{});
    pr::encode_command(bytes, pr::FrameBegin{1, 8, 6, pr::Rgb{}});
    pr::encode_time(bytes, pr::kSendTimeOpcode, 2000);
    pr::encode_command(bytes, pr::FillRect{0, 0, 2, 2, pr::Rgb{}});  // and the stream ends
    const std::string path = scratch("never_ended.fb89");
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    CliRun r = run_fb89("info " + path + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["frames"].size(), 2u);
    EXPECT_EQ(j["frames"][0]["host_end_us"].get<double>(), 3.0);
    EXPECT_TRUE(j["frames"][1]["host_end_us"].is_null()) << j["frames"][1];
    EXPECT_EQ(j["frames"][1]["last_send_us"].get<double>(), 2.0);
    r = run_fb89("info " + path);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto lines = complete_lines(r.out);
    ASSERT_FALSE(lines.empty());
    EXPECT_NE(lines.back().find("never ended"), std::string::npos) << r.out;
    EXPECT_EQ(lines.back().find("0.003000"), std::string::npos) << r.out;
}

TEST(DumpCommand, PrintsOneNumberedLinePerCommand) {
    const std::string stream = write_stream("three.fb89", three_frames());
    CliRun r = run_fb89("dump " + stream);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto lines = complete_lines(r.out);
    ASSERT_EQ(lines.size(), 12u) << r.out;
    EXPECT_EQ(lines[0].find("      0 @"), 0u) << lines[0];
    EXPECT_NE(lines[2].find("2 @"), std::string::npos);
    EXPECT_NE(lines[2].find("FILL_RECT x=0 y=0 w=4 h=4 color=#ff0000"), std::string::npos);
    EXPECT_NE(lines[1].find("MARKER \"warnock\""), std::string::npos);
}

TEST(DumpCommand, CallsAndGrepSelectLines) {
    const std::string stream = write_stream("three.fb89", three_frames());
    EXPECT_EQ(complete_lines(run_fb89("dump " + stream + " --calls /span").out).size(), 2u);
    EXPECT_EQ(complete_lines(run_fb89("dump " + stream + " --calls frame").out).size(), 3u);
    EXPECT_EQ(complete_lines(run_fb89("dump " + stream + " --calls 0-11/2").out).size(), 6u);
    EXPECT_EQ(complete_lines(run_fb89("dump " + stream + " --calls 6-").out).size(), 6u);
    CliRun grep = run_fb89("dump " + stream + " --grep 'color=#0+ff$'");
    ASSERT_EQ(complete_lines(grep.out).size(), 1u) << grep.out;
    EXPECT_NE(grep.out.find("      9 @"), std::string::npos) << grep.out;
}

TEST(DumpCommand, SeeksThroughTheFrameIndexPastACorruptFrame) {
    // corrupt frame 0's span (x1 < x0) but leave the index valid: reading from the start
    // fails there (version 1: at the span; version 4: frame 0's batch fails its checksum),
    // reading calls 5- seeks to frame 1 and never sees it
    for (const pr::Checksums checksums : {pr::Checksums::Off, pr::Checksums::On}) {
        auto bytes = pr::encode_stream(three_frames(), {{"scene", "built"}}, true, checksums);
        pr::StreamReader reader(bytes);
        pr::Command c;
        for (int i = 0; i < 4; ++i)
            ASSERT_TRUE(reader.next(c));
        const std::size_t span_at = reader.command_offset();  // command 3
        ASSERT_EQ(bytes[span_at], 0x03);
        bytes[span_at + 12] = 0x80;  // x1's top byte: x1 < 0 < x0
        const std::string path = scratch("bad0.fb89");
        std::ofstream(path, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()),
                   static_cast<std::streamsize>(bytes.size()));
        CliRun all = run_fb89("dump " + path);
        EXPECT_EQ(all.exit_code, 2);
        EXPECT_NE(all.err.find(checksums == pr::Checksums::On
                                   ? "batch 0 fails its checksum at byte 36 (commands 0-4)"
                                   : "(command 3)"),
                  std::string::npos)
            << all.err;
        CliRun later = run_fb89("dump " + path + " --calls 5-");
        EXPECT_EQ(later.exit_code, 0) << later.err;
        EXPECT_EQ(complete_lines(later.out).size(), 7u) << later.out;
    }
}

TEST(DumpCommand, BadCallSetExitsTwoNamingIt) {
    const std::string stream = write_stream("three.fb89", three_frames());
    CliRun r = run_fb89("dump " + stream + " --calls 5-2");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--calls: call set '5-2': at character 3"), std::string::npos) << r.err;
    CliRun re = run_fb89("dump " + stream + " --grep '('");
    EXPECT_EQ(re.exit_code, 2);
    EXPECT_NE(re.err.find("--grep"), std::string::npos) << re.err;
    CliRun past = run_fb89("dump " + stream + " --calls 99999999");
    EXPECT_EQ(past.exit_code, 2);
    EXPECT_NE(past.err.find("past the stream's last (it has 12 commands)"), std::string::npos)
        << past.err;
}

TEST(InfoCommand, JsonHasPerFrameOpcodesPixelsAndBytes) {
    const std::string stream = write_stream("three.fb89", three_frames());
    CliRun r = run_fb89("info " + stream + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["version"], 4);
    EXPECT_EQ(j["checksums"]["all_good"], true);
    EXPECT_EQ(j["checksums"]["batches_checked"], 4);  // a batch a frame, and the index's
    EXPECT_EQ(j["properties"]["scene"], "built");
    EXPECT_TRUE(j["frame_index"].get<bool>());
    EXPECT_EQ(j["commands"], 12);
    ASSERT_EQ(j["frames"].size(), 3u);
    const auto& f0 = j["frames"][0];
    EXPECT_EQ(f0["by_opcode"]["FILL_RECT"], 1);
    EXPECT_EQ(f0["by_opcode"]["MARKER"], 1);
    EXPECT_EQ(f0["pixels"], 48 + 16 + 6);              // clear, fill, span
    EXPECT_EQ(f0["bus_bytes"], 10 + 0 + 12 + 10 + 2);  // tms34010-50mhz
    EXPECT_EQ(f0["stream_bytes"], 16 + 10 + 20 + 16 + 1);
    EXPECT_EQ(j["frames"][1]["stream_bytes"], 16 + 20 + 1);

    // The ideal profile charges no time but counts the same bytes on the bus.
    CliRun ideal = run_fb89("info " + stream + " --json --profile ideal");
    ASSERT_EQ(ideal.exit_code, 0) << ideal.err;
    EXPECT_EQ(nlohmann::json::parse(ideal.out)["frames"][0]["bus_bytes"], f0["bus_bytes"]);
}

TEST(InfoCommand, TextShowsHeaderAndOneRowPerFrame) {
    const std::string stream = record_a();
    CliRun r = run_fb89("info " + stream);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("format version 4"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("batches, all good"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("zbuffer"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("256x195"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("frame index    present"), std::string::npos) << r.out;
}

TEST(InfoCommand, NewerVersionNamesBothVersions) {
    auto bytes = pr::encode_stream(three_frames());
    bytes[4] = 5;
    const std::string path = scratch("v5.fb89");
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    CliRun r = run_fb89("info " + path);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("v5.fb89"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("version 5"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("up to 4"), std::string::npos) << r.err;
}

TEST(TrimCommand, WholeFramesKeepTheirChecksums) {
    const std::string stream = write_stream("three.fb89", three_frames());
    const std::string out = scratch("frames12.fb89");
    CliRun r = run_fb89("trim " + stream + " --frames 1-2 -o " + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto original = replay_stats(stream);
    const auto trimmed = replay_stats(out);
    ASSERT_EQ(trimmed["controller"]["frames_closed"], 2);
    EXPECT_EQ(trimmed["controller"]["frames"][0]["checksum"],
              original["controller"]["frames"][1]["checksum"]);
    EXPECT_EQ(trimmed["controller"]["frames"][1]["checksum"],
              original["controller"]["frames"][2]["checksum"]);
    const auto info = nlohmann::json::parse(run_fb89("info --json " + out).out);
    EXPECT_EQ(info["properties"]["trimmed_from"], stream);
    EXPECT_EQ(info["properties"]["trim_frames"], "1-2");
    EXPECT_EQ(info["properties"]["scene"], "built");
    EXPECT_TRUE(info["frame_index"].get<bool>());
}

TEST(TrimCommand, AKeptCommandBringsItsFramesBeginAndEnd) {
    const std::string stream = write_stream("three.fb89", three_frames());
    const std::string out = scratch("call6.fb89");
    ASSERT_EQ(run_fb89("trim " + stream + " --calls 6 -o " + out).exit_code, 0);
    const auto lines = complete_lines(run_fb89("dump " + out).out);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_NE(lines[0].find("FRAME_BEGIN frame=1"), std::string::npos) << lines[0];
    EXPECT_NE(lines[1].find("FILL_RECT x=2"), std::string::npos) << lines[1];
    EXPECT_NE(lines[2].find("FRAME_END"), std::string::npos) << lines[2];
    // a slice of a recorded frame replays too
    const std::string a = record_a(), slice = scratch("slice.fb89");
    ASSERT_EQ(run_fb89("trim " + a + " --calls 100-300/2/span -o " + slice).exit_code, 0);
    EXPECT_EQ(replay_stats(slice)["controller"]["frames_closed"], 1);
    EXPECT_EQ(run_fb89("trim " + a + " --frames /span -o " + slice).exit_code, 2);
    EXPECT_EQ(run_fb89("trim " + a + " -o " + slice).exit_code, 2);
    EXPECT_EQ(run_fb89("trim " + a + " --frames 0 -o " + a).exit_code, 2);
}

TEST(TrimCommand, TruncatedInputLeavesNothingAndSalvageGivesAStreamThatReplays) {
    const auto full =
        pr::encode_stream(three_frames(), {{"scene", "built"}}, true, pr::Checksums::Off);
    const std::string stream =
        write_stream("cut.fb89", three_frames(), full.size() - kCutInFrame2, pr::Checksums::Off);
    const std::string out = scratch("from_cut.fb89");
    CliRun r = run_fb89("trim " + stream + " --calls 0- -o " + out);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("cut.fb89: truncated"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(out + ": not written (--salvage"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    r = run_fb89("trim --salvage " + stream + " --calls 0- -o " + out);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("fb89: warning: "), std::string::npos) << r.err;
    CliRun replay = run_fb89("replay -q " + out);
    EXPECT_EQ(replay.exit_code, 0) << replay.err;
}

TEST(TrimCommand, ASelectionMatchingNothingLeavesNoFile) {
    const std::string stream = write_stream("one.fb89", three_frames());
    const std::string out = scratch("f7.fb89");
    CliRun r = run_fb89("trim " + stream + " --frames 7 -o " + out);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("the selection matched no command"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("not written"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(DiffCommand, SameFramesExitZeroAcrossMethods) {
    const std::string z = record_a("z.fb89"), w = scratch("w.fb89");
    ASSERT_EQ(
        run_fb89("render " + kScenes + "/A.json --size 256x195 -q --method warnock --stream " + w)
            .exit_code,
        0);
    CliRun r = run_fb89("diff " + z + " " + w);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("identical: 1 frame(s)"), std::string::npos) << r.out;
    // an image asked for is written: the first frame, nothing in red
    const std::string image = scratch("same.png");
    r = run_fb89("diff " + z + " " + w + " --image " + image);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("identical: 1 frame(s); image of frame 0 (nothing differs): " + image),
              std::string::npos)
        << r.out;
    const auto png = fb89::controller::read_png(image);
    ASSERT_EQ(png.width, 256u);
    for (std::size_t i = 0; i < png.pixels.size(); i += 3)
        ASSERT_LE(png.pixels[i], 85) << "pixel " << i / 3 << " is red";
}

TEST(DiffCommand, ADifferentPixelExitsOneWithARedDiffImage) {
    auto changed = three_frames();
    changed[9] = pr::DrawSpan{0, 0, 6, pr::Rgb{0, 0, 255}};  // frame 2: one pixel fewer
    const std::string a = write_stream("a3.fb89", three_frames()),
                      b = write_stream("b3.fb89", changed);
    const std::string image = scratch("diff.png");
    CliRun r = run_fb89("diff " + a + " " + b + " --image " + image);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.out.find("differ in 1 of 3 frame(s)"), std::string::npos) << r.out;
    const auto png = fb89::controller::read_png(image);
    ASSERT_EQ(png.width, 8u);
    EXPECT_EQ(png.pixels[7 * 3], 255);  // (7, 0) differs: red
    EXPECT_EQ(png.pixels[7 * 3 + 2], 0);
    EXPECT_EQ(png.pixels[0], 0);  // (0, 0): blue/3
    EXPECT_EQ(png.pixels[2], 85);
    auto fewer = three_frames();
    fewer.resize(8);
    EXPECT_EQ(run_fb89("diff " + a + " " + write_stream("two.fb89", fewer)).exit_code, 1);
}

// The byte offset two bytes into the stream's first DRAW_SPAN record past `after`, found
// from the stream's own structure (its header's length depends on the recorded properties,
// such as the scene's path, so a fixed byte count would land anywhere).
uint64_t inside_a_span_after(const std::string& stream, uint64_t after) {
    pr::StreamReader reader(stream);
    pr::Command c;
    while (reader.next(c))
        if (std::holds_alternative<pr::DrawSpan>(c) && reader.command_offset() > after)
            return reader.command_offset() + 2;
    ADD_FAILURE() << "no DRAW_SPAN past byte " << after << " in " << stream;
    return 0;
}

TEST(ReplayTools, TheStreamRecordsABundledSceneByNameAndAnyOtherAsTheUserGaveIt) {
    const std::string stream = scratch("relative.fb89");
    // a bundled scene, however it is given, is recorded by its name: the stream's bytes do
    // not depend on where the checkout lives
    for (const std::string& given : std::vector<std::string>{"A", "A.json", kScenes + "/A.json"}) {
        CliRun r = run_fb89("render " + given + " --size 64x48 -q --stream " + stream,
                            "cd " + kScenes + " && ");
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_EQ(pr::StreamReader(stream).properties().at("scene"), "A") << given;
    }
    // another scene file: the path as given, relative staying relative
    const fs::path mine = fs::path(scratch("mine.json"));
    fs::copy_file(kScenes + "/A.json", mine, fs::copy_options::overwrite_existing);
    CliRun r = run_fb89("render mine.json --size 64x48 -q --stream " + stream,
                        "cd " + mine.parent_path().string() + " && ");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(pr::StreamReader(stream).properties().at("scene"), "mine.json");
}

TEST(ReplayTools, EveryToolReportsATruncatedStreamAndExitsTwo) {
    const std::string a = record_a();
    const std::string cut = scratch("cut.fb89");
    fs::copy_file(a, cut, fs::copy_options::overwrite_existing);
    fs::resize_file(cut, inside_a_span_after(a, 4000));
    for (const std::string& args :
         {"replay " + cut, "dump " + cut, "info " + cut, "info --json " + cut,
          "trim " + cut + " --frames 0 -o " + scratch("t.fb89"), "diff " + a + " " + cut}) {
        CliRun r = run_fb89(args);
        EXPECT_EQ(r.exit_code, 2) << args;
        // (version 4: the batch holding the span, read whole, is cut short)
        EXPECT_NE(r.err.find("cut.fb89: truncated batch "), std::string::npos)
            << args << ": " << r.err;
        EXPECT_NE(r.err.find(" at byte "), std::string::npos) << args << ": " << r.err;
    }
    for (const char* tool : {"replay", "dump", "info"}) {
        CliRun missing = run_fb89(std::string(tool) + " /nonexistent/s.fb89");
        EXPECT_EQ(missing.exit_code, 2) << tool;
        EXPECT_NE(missing.err.find("/nonexistent/s.fb89"), std::string::npos) << missing.err;
    }
    const std::string junk = scratch("junk.fb89");
    std::ofstream(junk) << "not a stream";
    CliRun bad = run_fb89("dump " + junk);
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("bad magic"), std::string::npos) << bad.err;
}

}  // namespace
