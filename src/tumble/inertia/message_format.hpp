#pragma once
// Numbers in the inertia module's error messages: six significant digits, enough to see what is
// wrong with a computed moment, short enough to read.
#include <fmt/format.h>

#include <string>

namespace tumble::inertia_detail {

inline std::string format_number(double value) {
  return fmt::format("{:.6g}", value);
}

}  // namespace tumble::inertia_detail
