#include "host/scene/scene_keys.h"

#include <stdexcept>
#include <string>

namespace fb89::host {

const std::vector<KeySection>& scene_key_sections() {
    static const std::vector<KeySection> sections = {
        {"scene", {"camera", "image", "background", "light", "objects", "name", "description"}},
        {"camera", {"projection", "eye", "look_at", "up", "fovy", "near", "far"}},
        {"camera screen", {"projection"}},
        {"image", {"width", "height"}},
        {"light", {"direction", "ambient"}},
        {"object polygons", {"polygon", "polygons", "material", "transform"}},
        {"object obj", {"obj", "material", "transform"}},
        {"material", {"color", "mirror", "emission", "mirror_faces"}},
        {"part material", {"color"}},
        {"transform", {"scale", "rotate", "translate"}},
        {"rotate", {"axis", "degrees"}},
        {"generator box", {"generator", "min", "max", "material", "transform"}},
        {"generator quad",
         {"generator", "origin", "u", "v", "divisions", "triangles", "checker", "material",
          "transform"}},
        {"generator sphere",
         {"generator", "center", "radius", "segments", "rings", "material", "transform"}},
        {"generator lathe", {"generator", "profile", "segments", "caps", "material", "transform"}},
        {"generator shell",
         {"generator", "turns", "segments_per_turn", "sides", "growth", "size", "tube",
          "translation", "aspect", "material", "transform"}},
        {"generator terrain",
         {"generator", "cells", "size", "height", "octaves", "seed", "material", "transform"}},
        {"generator array",
         {"generator", "count", "step", "colors", "parts", "material", "transform"}},
        {"generator scatter",
         {"generator", "count", "seed", "min", "max", "min_distance", "scale", "random_yaw",
          "color_jitter", "parts", "material", "transform"}},
        {"generator ideal", {"generator", "layers", "faces_per_layer", "cell", "gap", "material"}},
        {"generator random_triangles", {"generator", "count", "area", "seed", "material"}},
    };
    return sections;
}

const std::vector<std::string_view>& scene_keys(std::string_view section) {
    for (const KeySection& s : scene_key_sections())
        if (s.name == section) return s.keys;
    throw std::logic_error("no scene key section '" + std::string(section) + "'");
}

}  // namespace fb89::host
