#pragma once
#include <string>
#include <vector>

#include "tumble/scenario/scenario.hpp"

namespace tumble::cli {

struct RunArguments {
  std::string scenario;
  std::string out_dir = ".";
  std::vector<std::string> sets;  // NAME=VALUE
};

struct InertiaArguments {
  std::string scenario;
  std::string body;  // empty: every body
};

int run_command(const RunArguments& args);
int inertia_command(const InertiaArguments& args);

// Splits each NAME=VALUE; throws std::invalid_argument for a malformed one.
std::vector<ParameterOverride> parse_overrides(const std::vector<std::string>& sets);

}  // namespace tumble::cli
