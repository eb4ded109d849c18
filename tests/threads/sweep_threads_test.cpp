// A sweep's runs on two threads (each with its own parsed document and recorder) give the records
// one thread gives; built under ThreadSanitizer by scripts/test.sh, which would report a race.
#include <gtest/gtest.h>

#include <string>

#include "tumble/scenario/scenario_document.hpp"
#include "tumble/sweep/parameter_space.hpp"
#include "tumble/sweep/sweep.hpp"

namespace tumble {
namespace {

TEST(SweepOnThreads, TwoThreadsGiveOneThreadsRows) {
  for (const char* stem : {"tumbling_prism", "cubli"}) {
    SweepSpec spec;
    spec.path = std::string(TUMBLE_SOURCE_DIR) + "/examples/" + stem + ".yaml";
    spec.text = read_scenario_file(spec.path);
    const bool prism = std::string(stem) == "tumbling_prism";
    spec.varied = {prism ? "a" : "w0"};
    spec.outcomes = {parse_record(prism ? "w=min(prism.w3)" : "up=min(corner.angle) < -pi/4"),
                     parse_record(prism ? "E=mean(E)" : "lock=first(lock.axle)")};
    const auto points = grid_points(
        std::vector<VaryRange>{parse_vary(prism ? "a=3.5:4.5:6" : "w0=90:120:6", true)}, 100);
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
