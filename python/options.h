// Keyword arguments as the module's functions take them: each Python value checked for its
// type (a TypeError naming the keyword: never pybind11's own list of signatures) and, for
// numbers, against the command line's limits (frontend/option_limits.h: an fb89.OptionError
// in the command's words, the option named by its keyword), before any work starts.
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frontend/option_limits.h"

namespace fb89::python {

// An integer (int, numpy's integers; not bool) within `limit`. A float, even a whole one,
// is an OptionError ("repeat: 2.5 is not an integer"), as the command line's "--repeat 2.5";
// anything else a TypeError.
int64_t whole_number(const pybind11::handle& value, const frontend::OptionLimit& limit);
// A real number (int or float; not bool) within `limit`.
double real_number(const pybind11::handle& value, const frontend::OptionLimit& limit);
// A real number (int or float; not bool), with no limit of its own.
double real_number(const pybind11::handle& value, std::string_view keyword);

// A str; else a TypeError naming `keyword`.
std::string text(const pybind11::handle& value, std::string_view keyword);
// None, or a str.
std::optional<std::string> optional_text(const pybind11::handle& value, std::string_view keyword);
// A path: a str or an os.PathLike (pathlib.Path); None gives "" when `none_allowed`.
std::string path_text(const pybind11::handle& value, std::string_view keyword,
                      bool none_allowed = false);
// A list or tuple of str (one str alone is refused: it is a sequence of letters).
std::vector<std::string> text_list(const pybind11::handle& value, std::string_view keyword);
// True or False (or numpy's bool).
bool flag(const pybind11::handle& value, std::string_view keyword);

// size=: None (""), "WxH", or (W, H) of integers -> "WxH", each side within
// limits::kImageSide (frontend::parse_size checks the text).
std::string size_text(const pybind11::handle& value, std::string_view keyword = "size");
// threshold=, beam_threshold=: None, a number, or a name ("inf", "paper", "calibrated") ->
// the text --threshold takes.
std::optional<std::string> threshold_text(const pybind11::handle& value, std::string_view keyword);
// buffer=: None (""), a number of bytes, or "unbounded" -> the text --buffer takes.
std::string buffer_text(const pybind11::handle& value);

}  // namespace fb89::python
