// Typed access to scene-file JSON fields, with errors that name the file and the field
// path ("scenes/a.json: objects[2].material.color: expected 3 numbers in [0, 1]").
#pragma once

#include <string>
#include <string_view>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace fb89::host {

class JsonFields {
  public:
    JsonFields(const nlohmann::json& node, std::string file, std::string path)
        : m_node(node), m_file(std::move(file)), m_path(std::move(path)) {}

    bool has(const char* key) const { return m_node.is_object() && m_node.contains(key); }
    JsonFields child(const char* key) const;  // the field must exist
    JsonFields element(size_t index) const;   // array element
    size_t size() const;                      // array length; the node must be an array
    const nlohmann::json& node() const { return m_node; }
    std::string where(const char* key = nullptr) const;  // "file: path.key"

    [[noreturn]] void fail(const char* key, const std::string& expected) const;

    double number(const char* key) const;
    double number_in(const char* key, double lo, double hi) const;
    double number_or(const char* key, double fallback, double lo, double hi) const;
    int integer_in(const char* key, int lo, int hi) const;
    int integer_or(const char* key, int fallback, int lo, int hi) const;
    std::string string(const char* key) const;
    glm::dvec3 vec3(const char* key) const;
    glm::dvec3 vec3_or(const char* key, glm::dvec3 fallback) const;
    glm::dvec3 color(const char* key) const;  // 3 numbers in [0, 1]
    glm::dvec3 vec3_of_node() const;          // this node itself as [x, y, z]

    // Rejects keys not among the section's (scene_keys.h), so a misspelt field is an error,
    // not silently ignored.
    void only_keys(std::string_view section) const;

  private:
    const nlohmann::json& m_node;
    std::string m_file;
    std::string m_path;
};

}  // namespace fb89::host
