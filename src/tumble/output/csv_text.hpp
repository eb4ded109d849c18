#pragma once
// A text cell of a CSV file, quoted as RFC 4180 has it (a quote inside doubled): the events' and
// the sweeps' messages hold commas.
#include <string>

namespace tumble {

inline std::string csv_quoted(const std::string& text) {
  std::string cell = "\"";
  for (const char c : text) {
    if (c == '"') cell += '"';
    cell += c;
  }
  return cell + "\"";
}

}  // namespace tumble
