// The names a user gives fb89 -- hidden-surface methods, controller profiles, hosts and
// bundled scenes -- read from the registries that define them (host/methods.h,
// controller_sim/profile.h and its profiles/, period/host_profile.h and period/<isa>/profiles/,
// the data folder's scenes/), so that no help text, man page or error lists them by hand.
// The checks here throw UsageError with the nearest known name ("did you mean"); the
// validators hand the same message to CLI11, which reports it as a usage error.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "host/methods.h"

namespace fb89::frontend {

// Every hidden-surface method, in the paper's order (host::methods()).
std::vector<std::string> method_names();
// The built-in controller profiles, sorted.
std::vector<std::string> profile_names();
// The period hosts' built-in profiles ("sun3-60", "pc-386-25", ...).
std::vector<std::string> host_profile_names();
// What --host takes by name: "native", then every period host.
std::vector<std::string> host_names();
// The bundled scenes by name ("A", "demo", ...), sorted: the .json files of data_dir()/scenes.
std::vector<std::string> scene_names();
// The period hosts' instruction sets as people name them ("Motorola MC68020 + MC68881",
// "SPARC V7", ...), from period/<isa>/isa.json.
std::vector<std::string> instruction_set_names();

// "a, b or c" (`last` between the last two).
std::string name_list(const std::vector<std::string>& names, const std::string& last = "or");

// The method of that name; else a UsageError "unknown method 'x'; did you mean 'y'? (...)".
host::Method find_method(const std::string& name);
// A built-in controller profile, or a name that is a file (contains '/', ends in .json, or
// exists); else a UsageError naming the nearest built-in profile.
void check_profile_name(const std::string& name);
// native, a period host or a .json host profile; else a UsageError naming the nearest host.
void check_host_name(const std::string& name);
// A period host or a .json host profile (no native); else a UsageError as check_host_name.
void check_host_profile_name(const std::string& name);

// The checks above as CLI11 validators: a bad value is a usage error naming the option.
CLI::Validator method_validator();
CLI::Validator profile_validator();
CLI::Validator host_validator();
CLI::Validator host_profile_validator();
// One of `names` (a kind of name such as "method"), with the nearest when not.
CLI::Validator one_of_validator(const std::string& kind, std::vector<std::string> names);

// A message that lists the names it expected beside the one given -- "unknown filter
// '/spna'; expected a step or one of /fill /span ..." or "expected baseline, v3 or v4, got
// 'v5'" -- with the nearest of them after it ("; did you mean '/span'?"); any other message,
// or one that has its guess already, as it is.
std::string with_nearest_name(const std::string& message);

// The help of the options and arguments that take these names, each listing them all.
std::string method_option_help(const std::string& what);
std::string profile_option_help(const std::string& what = "Controller cost profile");
std::string host_option_help(const std::string& what);
std::string scene_argument_help(const std::string& what);
// Every name of each kind, a line each, for the foot of `fb89 --help`.
std::string names_summary();

}  // namespace fb89::frontend
