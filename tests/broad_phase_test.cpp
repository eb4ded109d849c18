// The broad phase (contact/broad_phase.hpp): a group's pairs far apart are not watched, and no
// touch is missed for it. Checked against what it must not change: the same gas of balls with
// every pair named on its own (always watched) meets in the same impacts at the same instants,
// no two balls ever overlap, and energy is what the impacts leave of it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scenario_run.hpp"
#include "tumble/contact/broad_phase.hpp"
#include "tumble/output/columns.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {
namespace {

// A reproducible sequence in [0, 1) on every platform (the standard library's distributions are
// not): a 64-bit linear congruential generator's top 53 bits.
class Sequence {
 public:
  double next() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state_ >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t state_ = 12345;
};

TEST(SweepAndPrune, FindsEveryOverlappingPairAndNoOther) {
  Sequence random;
  std::vector<AlignedBox> boxes(300);
  for (AlignedBox& box : boxes) {
    const Vec3 centre(random.next(), random.next(), 0.2 * random.next());
    const Vec3 half = 0.03 * Vec3(random.next(), random.next(), random.next());
    box = {centre - half, centre + half};
  }
  boxes[7] = boxes[3];                                   // one box on another
  boxes[9] = {boxes[8].hi, boxes[8].hi + Vec3::Ones()};  // touching at a corner counts
  std::set<std::pair<std::size_t, std::size_t>> expected, found;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      if ((boxes[i].lo.array() <= boxes[j].hi.array()).all() &&
          (boxes[j].lo.array() <= boxes[i].hi.array()).all()) {
        expected.emplace(i, j);
      }
    }
  }
  SweepAndPrune sweep(boxes.size());
  sweep.for_each_overlap(boxes, [&](std::size_t i, std::size_t j) {
    EXPECT_LT(i, j);
    EXPECT_TRUE(found.emplace(i, j).second) << "reported twice: " << i << ", " << j;
  });
  EXPECT_GT(expected.size(), 20u);
  EXPECT_EQ(found, expected);
}

constexpr double kRadius = 0.05;

// n balls (radius 0.05 m) on a jittered grid of 0.2 m in a closed box of six walls welded to
// ground, each with a velocity of up to 1 m/s along each axis; `gravity` down z; the contact
// `contacts` (its {...} with `name: hit`). Rows every 0.01 s.
std::string gas(int per_side, double gravity, const std::string& contact, double duration) {
  Sequence random;
  const double spacing = 4.0 * kRadius, width = per_side * spacing, wall = 0.05;
  std::string yaml = "tumble: 1\ngravity: [0, 0, " + std::to_string(-gravity) + "]\nbodies:\n";
  const int n = per_side * per_side * per_side;
  for (int i = 0; i < n; ++i) {
    const int index[3] = {i % per_side, (i / per_side) % per_side, i / (per_side * per_side)};
    double p[3], v[3];
    for (int k = 0; k < 3; ++k) {
      p[k] = -width / 2 + spacing / 2 + spacing * index[k] + kRadius * (random.next() - 0.5);
      v[k] = 2.0 * random.next() - 1.0;
    }
    yaml += "  b" + std::to_string(i) + ": {shape: sphere, radius: 0.05, mass: 0.1, position: [" +
            std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) +
            "], velocity: [" + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " +
            std::to_string(v[2]) + "]}\n";
  }
  const std::string W = std::to_string(width), T = std::to_string(wall),
                    at = std::to_string(width / 2 + wall / 2);
  yaml += "  xlo: {shape: box, size: [" + T + ", " + W + ", " + W + "], mass: 9, position: [-" +
          at + ", 0, 0]}\n";
  yaml += "  xhi: {shape: box, size: [" + T + ", " + W + ", " + W + "], mass: 9, position: [" + at +
          ", 0, 0]}\n";
  yaml += "  ylo: {shape: box, size: [" + W + ", " + T + ", " + W + "], mass: 9, position: [0, -" +
          at + ", 0]}\n";
  yaml += "  yhi: {shape: box, size: [" + W + ", " + T + ", " + W + "], mass: 9, position: [0, " +
          at + ", 0]}\n";
  yaml += "  zlo: {shape: box, size: [" + W + ", " + W + ", " + T +
          "], mass: 9, position: [0, 0, -" + at + "]}\n";
  yaml += "  zhi: {shape: box, size: [" + W + ", " + W + ", " + T +
          "], mass: 9, position: [0, 0, " + at + "]}\n";
  yaml += "joints:\n";
  for (const char* w : {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"}) {
    yaml +=
        "  fix_" + std::string(w) + ": {type: fixed, bodies: [ground, " + w + "], at: [0, 0, 0]}\n";
  }
  yaml += "contacts:\n" + contact;
  yaml += "simulate: {duration: " + std::to_string(duration) +
          ", integrator: dop853, rtol: 1e-10, atol: 1e-12, output_every: 0.01}\n";
  return yaml;
}

// The same gas's every pair named on its own, as `bodies: all` names them (hit_b0_b1, ...): each
// watched at every step.
std::string every_pair_named(int per_side) {
  std::vector<std::string> names;
  for (int i = 0; i < per_side * per_side * per_side; ++i) names.push_back("b" + std::to_string(i));
  std::string contacts;
  const std::vector<std::string> walls = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};
  for (std::size_t a = 0; a < names.size(); ++a) {
    const auto pair = [&](const std::string& other) {
      contacts += "  - {name: hit_" + names[a] + "_" + other + ", type: bodies, bodies: [" +
                  names[a] + ", " + other + "], friction: 0, restitution: 1}\n";
    };
    for (std::size_t b = a + 1; b < names.size(); ++b) pair(names[b]);
    for (const std::string& wall : walls) pair(wall);
  }
  return contacts;
}

// The least gap between two balls, and between a ball and the box's inside, at a row (m).
double least_gap(const test::Row& row, int balls, double half_width) {
  double least = std::numeric_limits<double>::infinity();
  for (int i = 0; i < balls; ++i) {
    const Vec3& r = row.states[static_cast<std::size_t>(i)].r_G;
    least = std::min(least, half_width - kRadius - r.cwiseAbs().maxCoeff());
    for (int j = i + 1; j < balls; ++j) {
      least =
          std::min(least, (r - row.states[static_cast<std::size_t>(j)].r_G).norm() - 2 * kRadius);
    }
  }
  return least;
}

// 27 balls in a box with no gravity, elastic and frictionless: a hard-sphere gas. The group
// `bodies: all` (screened) and every pair named on its own (watched at every step) meet in the
// same impacts, to the integrator's precision in their instants (their steps differ, as their
// states do: the group's pairs share one ledger entry; the gas's chaos grows that difference,
// past 1e-9 s after 1.5 s, so the runs are compared for their first 1.2 s, ~200 impacts); no
// two balls overlap at any row
// (a touch the broad phase missed would show as an overlap growing at the approach speed, ~1 m/s
// x 0.01 s); each impact is elastic, so E holds to round-off.
TEST(BroadPhase, AGasOfBallsMeetsAsWithEveryPairWatched) {
  const int per_side = 3, balls = 27;
  const std::string all =
      "  - {name: hit, type: bodies, bodies: all, friction: 0, restitution: 1}\n";
  const test::ScenarioRun screened = test::run_inline_scenario(gas(per_side, 0.0, all, 1.2), "all");
  const test::ScenarioRun watched =
      test::run_inline_scenario(gas(per_side, 0.0, every_pair_named(per_side), 1.2), "named");
  // 27 balls and 6 walls: 351 pairs of balls and 162 of a ball and a wall; none of two walls.
  ASSERT_EQ(screened.contacts.size(), 351u + 162u);
  ASSERT_EQ(watched.contacts.size(), screened.contacts.size());
  for (std::size_t c = 0; c < screened.contacts.size(); ++c) {
    ASSERT_EQ(screened.contacts[c].name, watched.contacts[c].name);
    EXPECT_TRUE(screened.contacts[c].screened);
    EXPECT_FALSE(watched.contacts[c].screened);
  }
  ASSERT_GT(screened.contact_events.size(), 100u);
  ASSERT_EQ(screened.contact_events.size(), watched.contact_events.size());
  for (std::size_t e = 0; e < screened.contact_events.size(); ++e) {
    const ContactEventRecord& a = screened.contact_events[e];
    const ContactEventRecord& b = watched.contact_events[e];
    ASSERT_EQ(a.contact, b.contact) << "event " << e << " at t = " << a.t;
    EXPECT_NEAR(a.t, b.t, 1e-9) << "event " << e;
  }
  const double half_width = per_side * 2.0 * kRadius;
  const double E0 = screened.rows.front().quantities.total_energy;
  for (const test::Row& row : screened.rows) {
    EXPECT_GE(least_gap(row, balls, half_width), -1e-9) << "t = " << row.t;
    EXPECT_NEAR(row.quantities.total_energy, E0, 1e-12 * E0) << "t = " << row.t;
  }
}

// 27 balls dropped into the box with gravity, e = 1/2 between balls and on the walls: they bounce,
// strike each other and lose energy at each impact, and no more. E never rises from one row to the
// next; E less its start is the work of the impacts, which the contacts' ledger (C.W) records;
// and no two balls overlap.
TEST(BroadPhase, BallsDroppedIntoABinLoseEnergyOnlyAtTheirImpacts) {
  const int per_side = 3, balls = 27;
  const std::string all =
      "  - {name: hit, type: bodies, bodies: all, friction: 0, restitution: 0.5}\n";
  const test::ScenarioRun run = test::run_inline_scenario(gas(per_side, 9.81, all, 0.5), "dropped");
  ASSERT_GT(run.contact_events.size(), 50u);
  test::expect_energy_never_rises(run, 1e-12);
  const double half_width = per_side * 2.0 * kRadius;
  const double E0 = run.rows.front().quantities.total_energy;
  const double KE_scale =
      std::max_element(run.rows.begin(), run.rows.end(),
                       [](const test::Row& a, const test::Row& b) {
                         return a.quantities.kinetic_energy < b.quantities.kinetic_energy;
                       })
          ->quantities.kinetic_energy;
  for (const test::Row& row : run.rows) {
    EXPECT_GE(least_gap(row, balls, half_width), -1e-9) << "t = " << row.t;
    double work = 0.0;
    for (const auto& element : row.extras.elements) work += element.work;
    EXPECT_NEAR(row.quantities.total_energy - E0, work, 1e-9 * KE_scale) << "t = " << row.t;
  }
  EXPECT_LT(run.rows.back().quantities.total_energy, E0 - 0.1 * KE_scale);
}

// `bodies: all`'s pairs pool their work in one entry of the ledger, the contact's (hit.P, hit.W),
// and have no columns of their own; a group that lists the same bodies has each pair's. The two
// runs of 8 balls dropped into the box for 0.4 s (their first impacts, before the many of their
// settling, where the two runs' different steps would grow apart) meet in the same impacts, to
// the integrator's precision in their instants, and the pool's work is the listed pairs' summed,
// to 1e-9 of the starting KE.
TEST(BroadPhase, AllPoolsItsPairsWorkInOneEntry) {
  std::string listed = "  - {name: hit, type: bodies, bodies: [";
  for (int i = 0; i < 8; ++i) listed += "b" + std::to_string(i) + ", ";
  listed += "xlo, xhi, ylo, yhi, zlo, zhi], friction: 0, restitution: 0.5}\n";
  const std::string all =
      "  - {name: hit, type: bodies, bodies: all, friction: 0, restitution: 0.5}\n";
  const test::ScenarioRun pooled = test::run_inline_scenario(gas(2, 9.81, all, 0.4), "pooled");
  // The same pairs (two walls, neither a sphere, make none in either).
  const test::ScenarioRun each = test::run_inline_scenario(gas(2, 9.81, listed, 0.4), "each");
  ASSERT_EQ(each.contacts.size(), pooled.contacts.size());
  const Scenario& scenario = pooled.scenario;
  const ColumnLayout layout = column_layout(scenario, *build_simulation_model(scenario));
  std::vector<std::string> names;
  for_each_column(layout, [&](std::string_view owner, std::string_view field, auto&&) {
    if (owner.rfind("hit", 0) == 0) names.push_back(std::string(owner) + "." + std::string(field));
  });
  EXPECT_EQ(names, (std::vector<std::string>{"hit.P", "hit.W"}));
  ASSERT_EQ(pooled.rows.back().extras.elements.size(), 1u);
  double listed_work = 0.0;
  for (const auto& element : each.rows.back().extras.elements) listed_work += element.work;
  const double pooled_work = pooled.rows.back().extras.elements[0].work;
  EXPECT_LT(pooled_work, -0.1);
  EXPECT_NEAR(pooled_work, listed_work,
              1e-9 * pooled.rows.front().quantities.kinetic_energy + 1e-9 * std::abs(pooled_work));
  ASSERT_EQ(pooled.contact_events.size(), each.contact_events.size());
  for (std::size_t e = 0; e < pooled.contact_events.size(); ++e) {
    EXPECT_EQ(pooled.contacts[pooled.contact_events[e].contact].name,
              each.contacts[each.contact_events[e].contact].name);
    EXPECT_NEAR(pooled.contact_events[e].t, each.contact_events[e].t, 1e-9);
  }
}

// A gas stopped part way and resumed from its checkpoint goes on exactly as the run that never
// stopped: the broad phase is no state of the run (each step screens from its own start, and
// where that changes which pairs are watched their event functions are evaluated again there),
// so the resumed run watches what the whole run watched. Every number of every row after the
// stop, and every impact, is the same double. So is a second run of the same prepared run.
TEST(BroadPhase, AResumedGasGoesOnAsTheRunThatNeverStopped) {
  const std::string all =
      "  - {name: hit, type: bodies, bodies: all, friction: 0, restitution: 1}\n";
  const Scenario scenario = test::load_inline_scenario(gas(3, 0.0, all, 1.0), "resumed");
  const std::shared_ptr<const SimulationModel> model = build_simulation_model(scenario);
  using Rows = std::vector<std::vector<double>>;
  const auto keep = [](Rows& rows) -> FullRowObserver {
    return [&rows](double t, std::span<const BodyState> states, const SystemQuantities& q,
                   const RowExtras& extras) {
      std::vector<double> row = {t, q.total_energy};
      for (const BodyState& s : states) {
        row.insert(row.end(), {s.r_G.x(), s.r_G.y(), s.r_G.z(), s.v_G.x(), s.v_G.y(), s.v_G.z()});
      }
      for (const ContactOutput& c : extras.contacts) row.push_back(c.slip_speed);
      rows.push_back(std::move(row));
    };
  };
  Rows whole_rows;
  PreparedSimulation whole = prepare_run(*model);
  const SimulationResult whole_result = run_simulation(whole, keep(whole_rows));
  ASSERT_TRUE(whole_result.report.completed) << whole_result.report.failure;
  // A prepared run serves run after run (a sweep's): the second starts watching every pair
  // again, whatever the first screened last, and is the first's to the bit.
  Rows again;
  run_simulation(whole, keep(again));
  EXPECT_TRUE(again == whole_rows);
  for (const double t1 : {0.13, 0.5, 0.77}) {
    SCOPED_TRACE("stopped at " + std::to_string(t1));
    std::optional<SimulationCheckpoint> checkpoint;
    Rows rows;
    PreparedSimulation first = prepare_run(*model);
    first.options.checkpoint_after = t1;
    first.options.stop_at_checkpoint = true;
    run_simulation(first, keep(rows), [&](SimulationCheckpoint k) { checkpoint = k; });
    ASSERT_TRUE(checkpoint.has_value());
    PreparedSimulation second = prepare_run(*model);
    const std::size_t before = rows.size();
    const SimulationResult resumed = resume_simulation(second, *checkpoint, keep(rows));
    ASSERT_TRUE(resumed.report.completed) << resumed.report.failure;
    EXPECT_GT(before, 1u);
    EXPECT_LT(before, whole_rows.size());
    EXPECT_TRUE(rows == whole_rows);
    ASSERT_EQ(resumed.contact_events.size(), whole_result.contact_events.size());
    for (std::size_t e = 0; e < resumed.contact_events.size(); ++e) {
      EXPECT_EQ(resumed.contact_events[e].t, whole_result.contact_events[e].t);
      EXPECT_EQ(resumed.contact_events[e].contact, whole_result.contact_events[e].contact);
    }
    EXPECT_EQ(resumed.report.stats.accepted_steps, whole_result.report.stats.accepted_steps);
  }
}

// `bodies: all`: every body whose shape touches another body's, but two obstacles welded to
// ground (which never move) and two bodies a joint joins (unless `joined: true`). A rod cannot
// touch another body, nor can a plate yet: they are left out.
TEST(BroadPhase, AllTakesEveryBodyThatCanTouch) {
  const std::string yaml =
      "tumble: 1\n"
      "gravity: [0, 0, -9.81]\n"
      "bodies:\n"
      "  a: {shape: sphere, radius: 0.1, mass: 1, position: [0, 0, 1]}\n"
      "  b: {shape: sphere, radius: 0.1, mass: 1, position: [1, 0, 1]}\n"
      "  arm: {shape: rod, length: 1, mass: 1, position: [0.5, 0, 2]}\n"
      "  floor: {shape: box, size: [4, 4, 0.1], mass: 9, position: [0, 0, -0.05]}\n"
      "  post: {shape: box, size: [0.1, 0.1, 1], mass: 9, position: [2, 0, 0.5]}\n"
      "joints:\n"
      "  f1: {type: fixed, bodies: [ground, floor], at: [0, 0, 0]}\n"
      "  f2: {type: fixed, bodies: [ground, post], at: [2, 0, 0]}\n"
      "  pin: {type: hinge, bodies: [a, arm], at: [0, 0, 2], axis: [0, 1, 0]}\n"
      "contacts:\n"
      "  - {name: hit, type: bodies, bodies: all, friction: 0.5}\n"
      "simulate: {duration: 0.1}\n";
  const Scenario scenario = test::load_inline_scenario(yaml, "all");
  std::vector<std::string> names;
  for (const ContactSpec& contact : scenario.contacts) {
    names.push_back(contact.name);
    EXPECT_TRUE(contact.screened);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"hit_a_b", "hit_a_floor", "hit_a_post", "hit_b_floor",
                                             "hit_b_post"}));
  const auto names_of = [](const Scenario& s) {
    std::vector<std::string> found;
    for (const ContactSpec& contact : s.contacts) found.push_back(contact.name);
    return found;
  };
  // A plate touches planes, not bodies (yet): left out as the rod is.
  const std::string b_a_plate = test::replaced(yaml, "  b: {shape: sphere, radius: 0.1,",
                                               "  b: {shape: plate, size: [0.4, 0.3],");
  EXPECT_EQ(names_of(test::load_inline_scenario(b_a_plate, "plate")),
            (std::vector<std::string>{"hit_a_floor", "hit_a_post"}));
  const std::string tied =
      test::replaced(yaml, "  pin: {type: hinge, bodies: [a, arm]",
                     "  tie: {type: hinge, bodies: [a, b], at: [0.5, 0, 1], axis: [0, 1, 0]}\n"
                     "  pin: {type: hinge, bodies: [a, arm]");
  EXPECT_EQ(names_of(test::load_inline_scenario(tied, "tied")),
            (std::vector<std::string>{"hit_a_floor", "hit_a_post", "hit_b_floor", "hit_b_post"}));
  EXPECT_EQ(names_of(test::load_inline_scenario(
                test::replaced(tied, "friction: 0.5}", "friction: 0.5, joined: true}"), "joined")),
            (std::vector<std::string>{"hit_a_b", "hit_a_floor", "hit_a_post", "hit_b_floor",
                                      "hit_b_post"}));
}

TEST(BroadPhase, AllNeedsTwoBodiesThatCanTouch) {
  test::expect_error(
      "tumble: 1\n"
      "bodies:\n"
      "  a: {shape: sphere, radius: 0.1, mass: 1}\n"
      "  arm: {shape: rod, length: 1, mass: 1, position: [0.5, 0, 0]}\n"
      "contacts:\n"
      "  - {name: hit, type: bodies, bodies: all, friction: 0.5}\n"
      "simulate: {duration: 0.1}\n",
      6, 39, "contacts[0].bodies", "`all` finds 1 body whose shape touches another body's");
}

}  // namespace
}  // namespace tumble
