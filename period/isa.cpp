#include "period/isa.h"

#include <stdexcept>

#include <nlohmann/json.hpp>

namespace fb89::period {

namespace {

InstructionSet parse(const InstructionSetSource& source) {
    const std::string origin(source.origin);
    InstructionSet s;
    try {
        const nlohmann::json j = nlohmann::json::parse(source.json);
        s.name = j.at("name").get<std::string>();
        s.description = j.at("description").get<std::string>();
        s.qemu = j.at("qemu").get<std::string>();
        s.qemu_options = j.at("qemu_options").get<std::vector<std::string>>();
        s.plugin_options = j.at("plugin_options").get<std::vector<std::string>>();
        s.env = j.at("env").get<std::string>();
        for (const auto& p : j.at("packages"))
            s.packages += (s.packages.empty() ? "" : ", ") + p.get<std::string>();
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(origin + ": " + e.what());
    }
    s.guest_path = source.guest_path;
    s.kernels_dir = source.kernels_dir;
    return s;
}

const std::vector<InstructionSet>& all() {
    static const std::vector<InstructionSet> sets = [] {
        std::vector<InstructionSet> v;
        for (const InstructionSetSource& source : instruction_set_sources())
            v.push_back(parse(source));
        return v;
    }();
    return sets;
}

}  // namespace

std::span<const InstructionSet> instruction_sets() {
    return all();
}

const InstructionSet& instruction_set(std::string_view name) {
    std::string known;
    for (const InstructionSet& s : all()) {
        if (s.name == name) return s;
        known += (known.empty() ? "" : ", ") + s.name;
    }
    throw std::runtime_error("unknown instruction set '" + std::string(name) +
                             "' (known: " + known + ")");
}

}  // namespace fb89::period
