// Where fb89 finds what it ships: the bundled scenes and docs, and the 1989 host's guest
// program and counting plugin. Installed (cmake --install), they sit beside the binary:
// PREFIX/bin/fb89, PREFIX/share/fb89/{scenes,docs}, PREFIX/libexec/fb89/; in the build tree
// they are the source tree's and the build's. $FB89_DATA_DIR overrides the data folder. The
// installed Python module finds the same folders from its own prefix (set_install_prefix).
// So every default works from any directory.
#pragma once

#include <filesystem>
#include <string>

namespace fb89::frontend {

std::filesystem::path executable_dir();
// Where an installed fb89 would sit: the executable's folder's parent, unless a front end that
// is not the fb89 binary (the Python module, run by python3) said where it is installed.
std::filesystem::path install_prefix();
void set_install_prefix(const std::filesystem::path& prefix);
std::filesystem::path data_dir();
// data_dir()/scenes/NAME (e.g. "A.json").
std::string bundled_scene(const std::string& name);

// Whether a scene argument is a path rather than a name: it holds a '/' or ends in .json,
// .obj or .tri.
bool is_scene_path(const std::string& argument);
// The scene file an argument names. A path (is_scene_path) is read as given: a relative one
// from the current folder only. A name is a file of that name in the current folder, else
// the bundled scene (data_dir()/scenes/NAME.json or .tri: "demo", "G"). Throws
// host::SceneError naming the argument when there is none: for a path, saying so when a
// bundled scene has its name; for a name, the nearest bundled one ("did you mean").
std::string resolve_scene(const std::string& argument);
// How tables and reports show a scene file: a bundled scene by its name ("G"), a file named
// by name_scene_file by that name, any other file as it was given.
std::string scene_display_name(const std::string& path);
// A scene file that stands for a scene given otherwise (the Python module's private file for
// a scene given as a dict): scene_display_name shows `name` for `path`, as given, until
// forget_scene_file.
void name_scene_file(const std::string& path, const std::string& name);
void forget_scene_file(const std::string& path);

// Points the emulator at an installed guest and plugin when fb89 runs from its install
// prefix (and the caller set neither $FB89_GUEST nor $FB89_COUNT_PLUGIN).
void use_installed_period_parts();

}  // namespace fb89::frontend
