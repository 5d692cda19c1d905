// `.tri` screen-space triangle sets: first line `W H N`, then N lines
// `id x0 y0 z0 x1 y1 z1 x2 y2 z2` (pixels, y down, z in [0,1], smaller nearer). Several
// triangles may share an id. The format of the coverage conformance fixtures.
#include <charconv>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "host/scene/polygon.h"
#include "host/scene/scene_error.h"
#include "host/scene/scene_loader.h"

namespace fb89::host {

namespace {

class LineReader {
  public:
    LineReader(std::string_view text, const std::string& name) : m_text(text), m_name(name) {}

    bool next_line() {
        while (m_pos < m_text.size()) {
            size_t end = m_text.find('\n', m_pos);
            if (end == std::string_view::npos) end = m_text.size();
            m_line = m_text.substr(m_pos, end - m_pos);
            m_pos = end + 1;
            ++m_number;
            if (m_line.find_first_not_of(" \t\r") != std::string_view::npos) return true;
        }
        return false;
    }

    template <typename T>
    T field(const char* what) {
        size_t start = m_line.find_first_not_of(" \t\r", m_cursor);
        if (start == std::string_view::npos) fail(fmt::format("missing {}", what));
        size_t end = m_line.find_first_of(" \t\r", start);
        if (end == std::string_view::npos) end = m_line.size();
        T value{};
        auto [ptr, ec] = std::from_chars(m_line.data() + start, m_line.data() + end, value);
        if (ec != std::errc() || ptr != m_line.data() + end)
            fail(fmt::format("{} is not a valid number: '{}'", what,
                             m_line.substr(start, end - start)));
        m_cursor = end;
        return value;
    }

    void start_fields() { m_cursor = 0; }
    void expect_end() {
        if (m_line.find_first_not_of(" \t\r", m_cursor) != std::string_view::npos)
            fail("unexpected extra fields");
    }
    [[noreturn]] void fail(const std::string& what) const {
        throw SceneError(fmt::format("{}: line {}: {}", m_name, m_number, what));
    }

  private:
    std::string_view m_text;
    const std::string& m_name;
    std::string_view m_line;
    size_t m_pos = 0, m_cursor = 0, m_number = 0;
};

glm::dvec3 id_color(uint32_t id) {
    uint32_t h = (id + 1) * 2654435761u;
    return {0.25 + 0.7 * ((h >> 8) & 255) / 255.0, 0.25 + 0.7 * ((h >> 16) & 255) / 255.0,
            0.25 + 0.7 * ((h >> 24) & 255) / 255.0};
}

}  // namespace

Scene parse_tri(std::string_view text, const std::string& name) {
    LineReader in(text, name);
    if (!in.next_line()) in.fail("empty file; expected a first line 'W H N'");
    in.start_fields();
    Scene scene;
    scene.source = name;
    scene.projection = Projection::Screen;
    scene.width = in.field<int>("width W");
    scene.height = in.field<int>("height H");
    long long n = in.field<long long>("triangle count N");
    in.expect_end();
    if (scene.width < 1 || scene.width > 16384 || scene.height < 1 || scene.height > 16384)
        in.fail("width and height must be in [1, 16384]");
    if (n < 0 || n > 50'000'000) in.fail("triangle count N must be in [0, 50000000]");

    std::set<uint32_t> ids;
    for (long long t = 0; t < n; ++t) {
        if (!in.next_line()) in.fail(fmt::format("expected {} triangles, found {}", n, t));
        in.start_fields();
        long long id = in.field<long long>("id");
        if (id < 0 || id >= (1 << 24) - 1) in.fail("id must be in [0, 16777214]");
        std::vector<glm::dvec3> v(3);
        for (auto& p : v) {
            p.x = in.field<double>("x");
            p.y = in.field<double>("y");
            p.z = in.field<double>("z");
        }
        in.expect_end();
        PolygonResult prepared = prepare_polygon(v);
        if (prepared.verdict == PolygonVerdict::NotFinite) in.fail(prepared.reason);
        ids.insert(static_cast<uint32_t>(id));  // a dropped triangle's id stays its own
        if (prepared.verdict == PolygonVerdict::Degenerate) {
            ++scene.dropped;
            scene.notes.push_back(
                fmt::format("{}: triangle {}: dropped ({})", name, t, prepared.reason));
            continue;
        }
        Material m;
        m.color = id_color(static_cast<uint32_t>(id));
        scene.faces.push_back({std::move(v), m, static_cast<uint32_t>(id), 0});
    }
    scene.face_count = static_cast<uint32_t>(ids.size());
    return scene;
}

}  // namespace fb89::host
