// Comparing two face-id buffers of one scene the way REFERENCES.md expects them to differ:
// not at all in coverage, and in ids only where two faces' depths tie within llvmpipe's
// 24-bit depth resolution. Also: our own face-id buffer, read off the simulated controller,
// and, for the ray peer, where two id buffers differ relative to the id boundaries of ours.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "host/raster/screen_scene.h"
#include "protocol/memory_buffer.h"

namespace fb89::peers {

// Two planes closer than this at a pixel centre are a depth tie: llvmpipe keeps depth in
// 24 bits (steps of 2^-24) and interpolates it in single precision.
inline constexpr double kDepthTie = 0x1.0p-20;

// llvmpipe anchors each attribute plane at the window origin, z = a0 + dzdx*x + dzdy*y with
// a0 = z(0, 0), and evaluates it in single precision; for a steep face a0 and the products
// reach tens or hundreds, so its depth at a pixel is uncertain by ulps of those terms. A real
// mismatch whose |dz| is below 2^-22 * (|a x| + |b y| + |c|), summed over the two planes
// (two float ulps of each plane's terms), is one llvmpipe cannot resolve either way.
inline constexpr double kFloatUlps = 0x1.0p-22;

struct Exactness {
    uint64_t coverage_mismatches = 0;  // one side background, the other a face
    uint64_t id_mismatches = 0;        // both sides a face, different ids
    uint64_t depth_ties = 0;           // id mismatches whose planes differ by < kDepthTie
    uint64_t real_mismatches = 0;      // id mismatches that are not depth ties
    uint64_t within_float_error = 0;   // real mismatches within kFloatUlps of llvmpipe's planes
    double max_dz = 0;                 // the largest |z_ours - z_llvmpipe| of an id mismatch
    std::string first;                 // the first coverage or real mismatch, for messages
};

// `ours` and `theirs` hold id + 1 per pixel (0 = background), row 0 at the top.
Exactness compare_face_ids(const host::ScreenScene& scene, std::span<const uint32_t> ours,
                           std::span<const uint32_t> theirs);

// Where two id buffers differ, and whether each such pixel lies on an id boundary of `ours`
// (a 4-neighbour with another id, a miss counting as an id), only touches one diagonally (an
// 8-neighbour with another id: the tip of a sliver less than a pixel wide), or lies inside a
// face.
struct IdAgreement {
    uint64_t pixels = 0;
    uint64_t differ = 0;
    uint64_t coverage = 0;       // of those, one side a miss
    uint64_t on_boundary = 0;    // of those, on an id boundary of ours (4-neighbours)
    uint64_t diagonal = 0;       // of those, with another id only among the diagonal neighbours
    uint64_t interior = 0;       // of those, with all 8 neighbours of ours' id
    std::string first_interior;  // the first interior disagreement, for messages
    double agreement() const { return pixels ? 1.0 - double(differ) / double(pixels) : 1.0; }
};

// `ours` and `theirs` hold id + 1 per pixel (0 = miss), row 0 at the top.
IdAgreement compare_with_boundaries(int width, int height, std::span<const uint32_t> ours,
                                    std::span<const uint32_t> theirs);

// Replays one frame of commands (a face-id pass) into the controller with the "ideal"
// profile and decodes its framebuffer into ids + 1, as the conformance tests do.
std::vector<uint32_t> controller_face_ids(const protocol::MemoryBuffer& frame);

}  // namespace fb89::peers
