// The kd-tree (host/trace/kd_tree.h) and the multi-level ray tracer (host/trace/mlrta.h): the
// kd-tree's walk finds what testing every piece finds, and lets no ray through a shared edge;
// mlrta's frame is the ray tracer's exactly, on every bundled scene, on exact ties and on beam
// corners lying on shared edges; where rays are incoherent its loss stays bounded.
#include "host/trace/mlrta.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "host/scene/scene_loader.h"
#include "tests/host/trace/trace_test_util.h"

namespace fb89::host {
namespace {

using testing::add_face;
using testing::add_square;
using testing::render_trace;
using testing::trace_options;
using testing::world_scene;

uint64_t lcg(uint64_t& state) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return state >> 11;
}
double uniform(uint64_t& state) {
    return static_cast<double>(lcg(state)) / 9007199254740992.0;
}

// `count` random triangles of size about `size` in the cube [-2, 2]^3, seen from (0, 0, 5).
Scene random_screen_triangles(int width, int height, int count, double size, uint64_t seed) {
    Scene s = world_scene(width, height);
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 c(uniform(seed) * 4 - 2, uniform(seed) * 4 - 2, uniform(seed) * 4 - 2);
        auto jitter = [&] {
            return glm::dvec3(uniform(seed) - 0.5, uniform(seed) - 0.5, uniform(seed) - 0.5) * size;
        };
        add_face(s, {c + jitter(), c + jitter(), c + jitter()},
                 {uniform(seed), uniform(seed), uniform(seed)});
    }
    return s;
}

TEST(KdTree, ClosestHitEqualsEveryPieceTriedInTurn) {
    const Scene s = random_screen_triangles(8, 8, 400, 0.8, 1989);
    TraceScene trace(s, true, 0);
    RayTracer tracer(trace, nullptr, Accel::Kd);
    EXPECT_GT(tracer.kd_tree().depth(), 4);
    uint64_t state = 7;
    TraceCounts counts;
    for (int r = 0; r < 2000; ++r) {
        const Ray ray{{uniform(state) * 6 - 3, uniform(state) * 6 - 3, uniform(state) * 6 - 3},
                      {uniform(state) - 0.5, uniform(state) - 0.5, uniform(state) - 0.5}};
        const Hit hit = tracer.closest_hit(ray, 0, kNoFace, counts);
        Hit brute{INFINITY, kNoFace};
        const RaySpace space(ray);
        for (uint32_t p = 0; p < trace.faces().size(); ++p) {
            double t;
            if (trace.intersect(ray, space, p, 0, t) && t < brute.t) brute = {t, p};
        }
        ASSERT_EQ(hit.piece, brute.piece) << "ray " << r;
        if (hit.piece != kNoFace) {
            ASSERT_EQ(hit.t, brute.t);
        }
    }
    EXPECT_GT(counts.kd_nodes, 0u);
    EXPECT_LT(counts.face_tests, 2000u * 400u / 4) << "the kd-tree should test few pieces";
}

TEST(KdTree, NoRaySlipsThroughSharedEdgesOrVertices) {
    const Scene scene = testing::lattice_through_pixel_centres(61, 6);
    TraceScene trace(scene, true, 0);
    RayTracer tracer(trace, nullptr, Accel::Kd);
    TraceCounts counts;
    RayTrace path;
    for (int y = 0; y < 61; ++y)
        for (int x = 0; x < 61; ++x) {
            tracer.trace_pixel(x, y, path, counts);
            ASSERT_EQ(path.count, 1) << "pixel " << x << "," << y;
        }
}

// mlrta and raytrace (with the BVH) on one scene: the same ids, the same image, and the rays
// beams saved: every ray the ray tracer casts, mlrta casts, but for the pixels beams decided.
void expect_the_ray_tracers_frame(const Scene& scene, const std::string& what) {
    const auto rays = render_trace(scene, trace_options("raytrace"));
    const auto ml = render_trace(scene, trace_options("mlrta"));
    EXPECT_EQ(ml.ids, rays.ids) << what;
    EXPECT_EQ(ml.pixels, rays.pixels) << what;
    const Counters& c = ml.stats.counters;
    EXPECT_EQ(c.get("rays") + c.get("pixels_by_beams"), rays.stats.counters.get("rays")) << what;
    EXPECT_EQ(c.get("pixels_by_beams") + c.get("pixels_by_rays"),
              static_cast<uint64_t>(scene.width) * scene.height)
        << what;
    EXPECT_GT(c.get("beams"), 0u) << what;
    EXPECT_EQ(c.get("beams"), c.get("entry_points") + c.get("beams_missed")) << what;
}

TEST(Mlrta, ShowsTheRayTracersFrameOnEveryBundledScene) {
    for (const auto& entry : std::filesystem::directory_iterator(FB89_SCENES_DIR)) {
        if (entry.path().extension() != ".json") continue;
        Scene scene = load_scene(entry.path().string());
        scene.width = 256;
        scene.height = 195;
        expect_the_ray_tracers_frame(scene, entry.path().filename().string());
    }
}

TEST(Mlrta, ShowsTheRayTracersFrameOnGAtFullSize) {
    const Scene scene = load_scene(std::string(FB89_SCENES_DIR) + "/G.json");
    ASSERT_EQ(scene.width, 1024);
    expect_the_ray_tracers_frame(scene, "G");
}

TEST(Mlrta, BeamCornersOnSharedEdgesLoseNoPixel) {
    expect_the_ray_tracers_frame(testing::lattice_through_pixel_centres(61, 6), "lattice");
    expect_the_ray_tracers_frame(testing::lattice_through_pixel_centres(129, 16), "lattice 16");
}

TEST(Mlrta, AnExactTieGoesToTheLowerPiece) {
    Scene s = world_scene(64, 64);
    add_square(s, 0, 0, 0, 1, {1, 0, 0});
    add_square(s, 0, 0, 0, 1, {0, 1, 0});  // the same square again: every hit ties
    add_square(s, 0.5, 0.5, 0, 1, {0, 0, 1});
    expect_the_ray_tracers_frame(s, "ties");
    const auto ml = render_trace(s, trace_options("mlrta"));
    EXPECT_GT(ml.stats.counters.get("ray_ties"), 0u);
}

TEST(Mlrta, MirrorsAreFollowedAsTheRayTracerFollowsThem) {
    Scene s = world_scene(96, 64);
    add_square(s, -1, 0, -1, 1.5, {0.9, 0.9, 0.9}, 0.8);  // a mirror
    add_square(s, 1.2, 0, 0.5, 0.6, {1, 0.2, 0.1});
    add_face(s, {{-3, -2, 1}, {3, -2, 1}, {0, -2, -3}}, {0.2, 0.8, 0.3}, 0.5);
    expect_the_ray_tracers_frame(s, "mirrors");
    const auto rays = render_trace(s, trace_options("raytrace"));
    EXPECT_GT(rays.stats.counters.get("rays"), 96u * 64u) << "the mirrors reflect";
}

TEST(Mlrta, AnEmptySceneIsDecidedByBeamsWithoutARay) {
    Scene s = world_scene(100, 70);
    add_square(s, 0, 0, 10, 1, {1, 1, 1});  // behind the eye: nothing in view
    const auto ml = render_trace(s, trace_options("mlrta"));
    const Counters& c = ml.stats.counters;
    EXPECT_EQ(c.get("rays"), 0u);
    EXPECT_EQ(c.get("pixels_by_beams"), 100u * 70u);
    EXPECT_EQ(c.get("spans"), 0u);
}

// Where it loses: many small triangles scattered in depth, so that the rays of a beam part at
// once and no entry point lies deep. The frame is still the ray tracer's, beams stop at the
// smallest size, and the walk's extra work (the beams' nodes and the rays' restarts from
// cells put off) stays within a bound of the kd-tree walked ray by ray from its root.
TEST(Mlrta, OnIncoherentRaysItsLossIsBoundedAndItsFrameExact) {
    const Scene s = random_screen_triangles(128, 128, 3000, 0.15, 42);
    expect_the_ray_tracers_frame(s, "incoherent");
    const auto kd = render_trace(s, trace_options("raytrace"));
    MethodOptions root_walk = trace_options("raytrace");
    root_walk.trace.accel = Accel::Kd;
    const auto from_root = render_trace(s, root_walk);
    const auto ml = render_trace(s, trace_options("mlrta"));
    const Counters& c = ml.stats.counters;
    const uint64_t root_nodes = from_root.stats.counters.get("kd_nodes_visited");
    const uint64_t ml_nodes =
        c.get("kd_nodes_visited") + c.get("beam_nodes_visited") + c.get("packet_nodes_visited");
    EXPECT_EQ(ml.ids, kd.ids);
    EXPECT_LE(ml_nodes, root_nodes * 3 / 2) << "the beams' walk and the rays' from entry points";
    EXPECT_LE(c.get("ray_face_tests"), from_root.stats.counters.get("ray_face_tests") * 3 / 2);
    // the beams split down to the smallest where rays part
    const uint64_t pixels = 128u * 128u;
    EXPECT_GE(c.get("beams"), pixels / (kMlrtaMinBeam * kMlrtaMinBeam));
}

// Packets of rays (ray_packet.h) whose lanes part: the eye looks along a diagonal with a wide
// view, so that the axis a ray runs along most changes inside packets (those rays go alone),
// the random triangles' planes fall between the starts of a packet's rays (each side's lanes
// walk on their own), and a third of them are mirrors, whose reflected rays go on in packets
// that part again. The frame is the ray tracer's at every kernel level, and every
// count but the packets' node visits (a packet of 8 lanes visits a node once, of 2 lanes four
// times) is the same at every level. Its rays one by one (packets off) make the same frame.
TEST(Mlrta, PacketsWhoseRaysPartStayExactAtEveryKernelLevel) {
    Scene s = random_screen_triangles(96, 80, 1500, 0.3, 7);
    for (size_t i = 0; i < s.faces.size(); i += 3)
        s.faces[i].material.mirror = 0.7;  // reflected rays go in packets too, and part
    s.camera.eye = {-4.5, 0.5, 4.5};
    s.camera.look_at = {0, 0, 0};
    s.camera.fovy_degrees = 100;
    const KernelLevel was = kernel_level();
    set_kernel_level(KernelLevel::Baseline);
    const auto rays = render_trace(s, trace_options("raytrace"));
    const auto base = render_trace(s, trace_options("mlrta"));
    EXPECT_EQ(base.ids, rays.ids);
    EXPECT_EQ(base.pixels, rays.pixels);
    Counters base_counts = base.stats.counters;
    EXPECT_GT(base_counts.get("packets"), 0u);
    EXPECT_GT(base_counts.get("kd_nodes_visited") + base_counts.get("bvh_nodes_visited"), 0u)
        << "some rays go alone";
    EXPECT_GT(base_counts.get("rays"), base_counts.get("pixels_by_rays")) << "mirrors reflect";
    for (KernelLevel level : supported_kernel_levels()) {
        SCOPED_TRACE(std::string(kernel_level_name(level)));
        set_kernel_level(level);
        const auto ml = render_trace(s, trace_options("mlrta"));
        EXPECT_EQ(ml.ids, rays.ids);
        EXPECT_EQ(ml.pixels, rays.pixels);
        MethodOptions one_by_one = trace_options("mlrta");
        one_by_one.trace.packets = false;
        const auto scalar = render_trace(s, one_by_one);
        EXPECT_EQ(scalar.ids, rays.ids);
        EXPECT_EQ(scalar.pixels, rays.pixels);
        EXPECT_EQ(scalar.stats.counters.get("packets"), 0u);
        EXPECT_EQ(scalar.stats.counters.get("rays"), base_counts.get("rays"));
        for (const auto& [name, value] : base_counts.items()) {
            if (name == "packet_nodes_visited") continue;
            EXPECT_EQ(ml.stats.counters.get(name), value) << name;
        }
    }
    set_kernel_level(was);
}

TEST(Mlrta, RefusesTheGrid) {
    MethodOptions o(Method::Mlrta);
    o.trace.accel = Accel::Grid;
    EXPECT_THROW(make_renderer(o), std::invalid_argument);
    o.trace.accel = Accel::Kd;
    EXPECT_NO_THROW(make_renderer(o));
    MethodOptions beam(Method::Beam);
    beam.trace.accel = Accel::Kd;
    EXPECT_THROW(make_renderer(beam), std::invalid_argument);
}

}  // namespace
}  // namespace fb89::host
