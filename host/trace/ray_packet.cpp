#include "host/trace/ray_packet.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <utility>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include <glm/common.hpp>

namespace fb89::host {

void RayPacket::fill_empty_lanes() {
    const int from = std::countr_zero(lanes);
    for (int i = 0; i < kPacketRays; ++i)
        if (!(lanes >> i & 1)) {
            for (int k = 0; k < 3; ++k) {
                origin[k][i] = origin[k][from];
                dir[k][i] = dir[k][from];
            }
            tmin[i] = tmin[from];
            skip[i] = skip[from];
        }
}

void PacketMailbox::begin() {
    if (++m_serial == 0) {
        std::fill(m_seen.begin(), m_seen.end(), Seen{});
        m_serial = 1;
    }
}

// Each level's kernel: its namespace, its instruction set (the standard library, glm and the
// project's headers were included above, compiled for the baseline, so that no inline function
// they define is compiled for a wider set by mistake).
#if defined(__x86_64__) && !defined(FB89_PORTABLE_KERNELS)
#define FB89_PACKET_ISA 2
#else
#define FB89_PACKET_ISA 0
#endif
namespace packet_baseline {
constexpr int kLanes = 2;
#include "host/trace/ray_packet_kernel.inc"
}  // namespace packet_baseline

#if defined(__x86_64__) && !defined(FB89_PORTABLE_KERNELS)
#pragma GCC push_options
#pragma GCC target("arch=x86-64-v3")
#undef FB89_PACKET_ISA
#define FB89_PACKET_ISA 3
namespace packet_v3 {
constexpr int kLanes = 4;
#include "host/trace/ray_packet_kernel.inc"
}  // namespace packet_v3
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("arch=x86-64-v4")
#undef FB89_PACKET_ISA
#define FB89_PACKET_ISA 4
namespace packet_v4 {
constexpr int kLanes = 8;
#include "host/trace/ray_packet_kernel.inc"
}  // namespace packet_v4
#pragma GCC pop_options
#endif
#undef FB89_PACKET_ISA

PacketTracer packet_tracer(KernelLevel level) {
#if defined(__x86_64__) && !defined(FB89_PORTABLE_KERNELS)
    if (level == KernelLevel::V4) return packet_v4::trace;
    if (level == KernelLevel::V3) return packet_v3::trace;
#endif
    (void)level;
    return packet_baseline::trace;
}

}  // namespace fb89::host
