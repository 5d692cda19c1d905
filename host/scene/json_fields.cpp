#include "host/scene/json_fields.h"

#include <cmath>

#include <fmt/format.h>

#include "host/scene/scene_error.h"
#include "host/scene/scene_keys.h"

namespace fb89::host {

namespace {
std::string join(const std::string& path, const char* key) {
    if (!key) return path;
    return path.empty() ? std::string(key) : path + "." + key;
}

std::string describe(const nlohmann::json& v) {
    std::string s = v.dump();
    return s.size() > 40 ? s.substr(0, 37) + "..." : s;
}
}  // namespace

std::string JsonFields::where(const char* key) const {
    std::string p = join(m_path, key);
    return p.empty() ? m_file : m_file + ": " + p;
}

void JsonFields::fail(const char* key, const std::string& expected) const {
    std::string got;
    if (key && m_node.is_object() && m_node.contains(key))
        got = fmt::format(", got {}", describe(m_node.at(key)));
    else if (key)
        got = ", but it is missing";
    else
        got = fmt::format(", got {}", describe(m_node));
    throw SceneError(fmt::format("{}: expected {}{}", where(key), expected, got));
}

JsonFields JsonFields::child(const char* key) const {
    if (!has(key)) fail(key, "a value");
    return JsonFields(m_node.at(key), m_file, join(m_path, key));
}

JsonFields JsonFields::element(size_t index) const {
    return JsonFields(m_node.at(index), m_file, fmt::format("{}[{}]", m_path, index));
}

size_t JsonFields::size() const {
    if (!m_node.is_array()) fail(nullptr, "an array");
    return m_node.size();
}

double JsonFields::number(const char* key) const {
    if (!has(key) || !m_node.at(key).is_number()) fail(key, "a number");
    double v = m_node.at(key).get<double>();
    if (!std::isfinite(v)) fail(key, "a finite number");
    return v;
}

double JsonFields::number_in(const char* key, double lo, double hi) const {
    double v = number(key);
    if (v < lo || v > hi) fail(key, fmt::format("a number in [{}, {}]", lo, hi));
    return v;
}

double JsonFields::number_or(const char* key, double fallback, double lo, double hi) const {
    return has(key) ? number_in(key, lo, hi) : fallback;
}

int JsonFields::integer_in(const char* key, int lo, int hi) const {
    if (!has(key) || !m_node.at(key).is_number_integer())
        fail(key, fmt::format("an integer in [{}, {}]", lo, hi));
    auto v = m_node.at(key).get<long long>();
    if (v < lo || v > hi) fail(key, fmt::format("an integer in [{}, {}]", lo, hi));
    return static_cast<int>(v);
}

int JsonFields::integer_or(const char* key, int fallback, int lo, int hi) const {
    return has(key) ? integer_in(key, lo, hi) : fallback;
}

std::string JsonFields::string(const char* key) const {
    if (!has(key) || !m_node.at(key).is_string()) fail(key, "a string");
    return m_node.at(key).get<std::string>();
}

glm::dvec3 JsonFields::vec3_of_node() const {
    const auto& a = m_node;
    bool ok = a.is_array() && a.size() == 3;
    for (size_t i = 0; ok && i < 3; ++i)
        ok = a[i].is_number() && std::isfinite(a[i].get<double>());
    if (!ok) fail(nullptr, "an array of 3 finite numbers");
    return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>()};
}

glm::dvec3 JsonFields::vec3(const char* key) const {
    if (!has(key)) fail(key, "an array of 3 finite numbers");
    return child(key).vec3_of_node();
}

glm::dvec3 JsonFields::vec3_or(const char* key, glm::dvec3 fallback) const {
    return has(key) ? vec3(key) : fallback;
}

glm::dvec3 JsonFields::color(const char* key) const {
    glm::dvec3 c = vec3(key);
    for (int i = 0; i < 3; ++i)
        if (c[i] < 0 || c[i] > 1) fail(key, "3 numbers in [0, 1]");
    return c;
}

void JsonFields::only_keys(std::string_view section) const {
    if (!m_node.is_object()) fail(nullptr, "an object");
    const std::vector<std::string_view>& allowed = scene_keys(section);
    for (const auto& item : m_node.items()) {
        bool known = false;
        for (std::string_view k : allowed)
            known = known || item.key() == k;
        if (!known) {
            std::string list;
            for (std::string_view k : allowed)
                list += (list.empty() ? "" : ", ") + std::string(k);
            throw SceneError(fmt::format("{}: unknown field '{}' (expected one of: {})", where(),
                                         item.key(), list));
        }
    }
}

}  // namespace fb89::host
