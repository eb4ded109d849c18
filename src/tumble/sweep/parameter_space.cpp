#include "tumble/sweep/parameter_space.hpp"

#include <fmt/format.h>
#include <charconv>
#include <random>
#include <stdexcept>

#include "tumble/scenario/expression.hpp"

namespace tumble {
namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t at = text.find(separator); at != std::string::npos;
       at = text.find(separator, start)) {
    parts.push_back(text.substr(start, at - start));
    start = at + 1;
  }
  parts.push_back(text.substr(start));
  return parts;
}

}  // namespace

VaryRange parse_vary(const std::string& argument, bool with_count) {
  VaryRange range;
  range.argument = argument;
  const std::string form = with_count ? "NAME=START:STOP:COUNT" : "NAME=LO:HI";
  const auto fail = [&](const std::string& why) -> void {
    throw std::invalid_argument(fmt::format("--vary {}: {}", argument, why));
  };
  const auto eq = argument.find('=');
  if (eq == std::string::npos || eq == 0) fail("expected " + form);
  range.name = argument.substr(0, eq);
  const std::vector<std::string> parts = split(argument.substr(eq + 1), ':');
  if (parts.size() != (with_count ? 3u : 2u)) {
    fail("expected " + form +
         (with_count ? " (with --random, or for find, NAME=LO:HI)" : " (no COUNT here)"));
  }
  const ExpressionEvaluator constants;  // pi, e and the units
  const auto bound = [&](const std::string& text, const char* which) {
    try {
      return constants.evaluate(text);
    } catch (const ExpressionError& error) {
      fail(fmt::format("{}: {}", which, error.what()));
    }
    return 0.0;
  };
  range.start = bound(parts[0], with_count ? "START" : "LO");
  range.stop = bound(parts[1], with_count ? "STOP" : "HI");
  if (with_count) {
    long count = 0;
    const std::string& text = parts[2];
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), count);
    if (error != std::errc() || end != text.data() + text.size()) {
      fail("COUNT must be a whole number, got '" + text + "'");
    }
    if (count < 1) fail("empty range: COUNT must be at least 1");
    if (count > 1 && range.start == range.stop) {
      fail("empty range: START equals STOP (give COUNT 1 for the one value)");
    }
    range.count = count;
  } else if (!(range.start < range.stop)) {
    fail("empty range: LO must be below HI");
  }
  return range;
}

std::vector<std::vector<double>> grid_points(std::span<const VaryRange> ranges,
                                             std::size_t max_points) {
  std::size_t total = 1;
  for (const VaryRange& r : ranges) {
    if (static_cast<std::size_t>(r.count) > max_points / total) {
      throw std::invalid_argument(
          fmt::format("the grid has more than {} points: give fewer values", max_points));
    }
    total *= static_cast<std::size_t>(r.count);
  }
  std::vector<std::vector<double>> points;
  points.reserve(total);
  std::vector<long> index(ranges.size(), 0);
  for (std::size_t n = 0; n < total; ++n) {
    std::vector<double> point;
    for (std::size_t k = 0; k < ranges.size(); ++k) {
      const VaryRange& r = ranges[k];
      const long i = index[k];
      const double fraction =
          r.count == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(r.count - 1);
      point.push_back(r.count > 1 && i == r.count - 1 ? r.stop
                                                      : r.start + (r.stop - r.start) * fraction);
    }
    points.push_back(std::move(point));
    for (std::size_t k = ranges.size(); k-- > 0;) {  // the last range fastest
      if (++index[k] < ranges[k].count) break;
      index[k] = 0;
    }
  }
  return points;
}

std::vector<std::vector<double>> random_points(std::span<const VaryRange> ranges, std::size_t count,
                                               std::uint64_t seed) {
  std::mt19937_64 bits(seed);
  std::vector<std::vector<double>> points(count);
  for (std::vector<double>& point : points) {
    for (const VaryRange& r : ranges) {
      const double u = static_cast<double>(bits() >> 11) * 0x1.0p-53;  // [0, 1)
      point.push_back(r.start + (r.stop - r.start) * u);
    }
  }
  return points;
}

}  // namespace tumble
