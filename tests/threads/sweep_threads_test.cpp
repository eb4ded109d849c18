// A sweep's runs on two threads (each with its own parsed document and recorder) give the records
// one thread gives, the backspin disk's (whose speed reaches only its initial state) on one model
// that both threads run; built under ThreadSanitizer by scripts/test.sh, which would report a
// race.
#include <gtest/gtest.h>

#include <string>

#include "tumble/scenario/scenario_document.hpp"
#include "tumble/sweep/parameter_space.hpp"
#include "tumble/sweep/sweep.hpp"

namespace tumble {
namespace {

TEST(SweepOnThreads, TwoThreadsGiveOneThreadsRows) {
  struct Case {
    const char* stem;
    const char* vary;
    const char* records[2];
  };
  for (const Case& c :
       {Case{"tumbling_prism", "a=3.5:4.5:6", {"w=min(prism.w3)", "E=mean(E)"}},
        Case{"cubli", "w0=90:120:6", {"up=min(corner.angle) < -pi/4", "lock=first(lock.axle)"}},
        Case{"backspin_disk", "v0=1:3:6", {"roll=first(floor.rolls)", "v=final(disk.vx)"}}}) {
    const std::string stem = c.stem;
    SweepSpec spec;
    spec.path = std::string(TUMBLE_SOURCE_DIR) + "/examples/" + stem + ".yaml";
    spec.text = read_scenario_file(spec.path);
    const VaryRange range = parse_vary(c.vary, true);
    spec.varied = {range.name};
    spec.outcomes = {parse_record(c.records[0]), parse_record(c.records[1])};
    const auto points = grid_points(std::vector<VaryRange>{range}, 100);
    const std::vector<RunRecord> one = run_points(spec, points, 1);
    const std::vector<RunRecord> two = run_points(spec, points, 2);
    for (std::size_t i = 0; i < points.size(); ++i) {
      EXPECT_EQ(sweep_csv_line(i, points[i], one[i], 2), sweep_csv_line(i, points[i], two[i], 2))
          << stem;
      EXPECT_EQ(one[i].status, RunStatus::Ok) << one[i].message;
    }
  }
}

}  // namespace
}  // namespace tumble
