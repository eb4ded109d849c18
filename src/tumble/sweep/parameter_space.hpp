#pragma once
// The points a sweep runs at: every combination of the varied parameters' values (a grid), or
// seeded uniform draws between their bounds. The same arguments give the same points, in the
// same order, on every machine.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tumble {

struct VaryRange {
  std::string argument;  // as given, for messages
  std::string name;
  double start = 0.0, stop = 0.0;
  long count = 0;  // values on the grid; 0 where only bounds were given (NAME=LO:HI)
};

// "NAME=START:STOP:COUNT" (with_count) or "NAME=LO:HI"; the bounds are numbers or expressions of
// constants and units ("pi/4", "30 deg", "1500 rpm"). Throws std::invalid_argument naming the
// argument for a malformed one or an empty range (COUNT < 1, START = STOP with COUNT > 1,
// LO >= HI).
VaryRange parse_vary(const std::string& argument, bool with_count);

// The grid's points, each with one value per range: the first range varies slowest, the last
// fastest; COUNT values from START to STOP inclusive, evenly spaced (the last is STOP exactly).
// Throws std::invalid_argument past max_points.
std::vector<std::vector<double>> grid_points(std::span<const VaryRange> ranges,
                                             std::size_t max_points);
// `count` points drawn uniformly in [LO, HI) of each range, from a 64-bit Mersenne Twister seeded
// with `seed` (the standard fixes its sequence; the draw to [0, 1) is the top 53 bits).
std::vector<std::vector<double>> random_points(std::span<const VaryRange> ranges, std::size_t count,
                                               std::uint64_t seed);

}  // namespace tumble
