#include "host/trace/kernel_level.h"

#include <atomic>
#include <cstdlib>
#include <stdexcept>

namespace fb89::host {

namespace {

bool cpu_has([[maybe_unused]] KernelLevel level) {
#if defined(__x86_64__) && !defined(FB89_PORTABLE_KERNELS)
    __builtin_cpu_init();
    switch (level) {
        case KernelLevel::Baseline:
            return true;
        case KernelLevel::V3:
            return __builtin_cpu_supports("x86-64-v3");
        case KernelLevel::V4:
            return __builtin_cpu_supports("x86-64-v4");
    }
    return false;
#else
    return level == KernelLevel::Baseline;
#endif
}

std::string level_list() {
    std::string out;
    for (KernelLevel l : supported_kernel_levels())
        out += (out.empty() ? "" : ", ") + std::string(kernel_level_name(l));
    return out;
}

KernelLevel initial_level() {
    if (const char* forced = std::getenv("FB89_ISA"); forced && *forced) {
        KernelLevel level;
        try {
            level = parse_kernel_level(forced);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(std::string("$FB89_ISA: ") + e.what());
        }
        for (KernelLevel l : supported_kernel_levels())
            if (l == level) return level;
        throw std::invalid_argument("$FB89_ISA: " + std::string(forced) +
                                    " is not supported here (this machine runs " + level_list() +
                                    ")");
    }
    return supported_kernel_levels().back();
}

std::atomic<int>& current() {
    static std::atomic<int> level{static_cast<int>(initial_level())};
    return level;
}

}  // namespace

std::string_view kernel_level_name(KernelLevel level) {
    switch (level) {
        case KernelLevel::Baseline:
            return "baseline";
        case KernelLevel::V3:
            return "v3";
        case KernelLevel::V4:
            return "v4";
    }
    return "?";
}

std::string_view kernel_level_description(KernelLevel level) {
#if defined(__x86_64__) && !defined(FB89_PORTABLE_KERNELS)
    switch (level) {
        case KernelLevel::Baseline:
            return "x86-64 (SSE2)";
        case KernelLevel::V3:
            return "x86-64-v3 (AVX2)";
        case KernelLevel::V4:
            return "x86-64-v4 (AVX-512)";
    }
    return "?";
#else
    (void)level;
    return "portable";
#endif
}

KernelLevel parse_kernel_level(std::string_view name) {
    for (KernelLevel l : {KernelLevel::Baseline, KernelLevel::V3, KernelLevel::V4})
        if (name == kernel_level_name(l)) return l;
    throw std::invalid_argument("expected baseline, v3 or v4, got '" + std::string(name) + "'");
}

const std::vector<KernelLevel>& supported_kernel_levels() {
    static const std::vector<KernelLevel> levels = [] {
        std::vector<KernelLevel> out;
        for (KernelLevel l : {KernelLevel::Baseline, KernelLevel::V3, KernelLevel::V4})
            if (cpu_has(l)) out.push_back(l);
        return out;
    }();
    return levels;
}

KernelLevel kernel_level() {
    return static_cast<KernelLevel>(current().load());
}

void set_kernel_level(KernelLevel level) {
    for (KernelLevel l : supported_kernel_levels())
        if (l == level) {
            current() = static_cast<int>(level);
            return;
        }
    throw std::invalid_argument(std::string(kernel_level_name(level)) +
                                " is not supported here (this machine runs " + level_list() + ")");
}

}  // namespace fb89::host
