#pragma once
// The animation page of `tumble run --animate`: ONE self-contained HTML file that shows the
// bodies with their true shapes moving through the recorded rows over the planes they touch,
// their axes, the angular velocity and the angular momentum about the COM, a trail of the COM,
// and the time plots of omega (body and world axes), KE / PE / E and |L|, then the scenario's own
// plots of chosen columns (animation_plots.hpp), with a cursor that follows the animation and the
// run's events marked on every plot.
// three.js and uPlot are embedded (animation_assets.hpp): the page makes no network request.
//
// The trajectory is embedded as base64 in a <script type="application/json"> element: per row
// t, KE, PE, E, |L| (float64) and per body r_G, q_WB, omega_W, omega_B, L_G_W (float32), about
// 100 bytes a row for one body. Every name from the scenario is JSON-escaped so that no "<" can
// end the element early, and the page shows names as text only.
#include <array>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "tumble/body/rigid_body.hpp"
#include "tumble/inertia/shapes.hpp"
#include "tumble/output/animation_plots.hpp"
#include "tumble/output/columns.hpp"
#include "tumble/output/output_row.hpp"
#include "tumble/scenario/scenario.hpp"

namespace tumble {

// One drawable piece of a body, placed in the body's frame relative to its COM.
struct AnimationPart {
  std::string name;
  Shape shape;
  Vec3 position_GP_B = Vec3::Zero();  // part frame origin from the body's COM, body axes, m
  Mat3 R_BP = Mat3::Identity();       // part axes -> body axes
  // A mesh: its triangles in the part's frame (at the mesh's COM). Empty when the mesh cannot
  // be passed (then the page draws the box [min, max] and says so in `note`).
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
  Vec3 box_min = Vec3::Zero();  // m, part frame: the mesh's bounding box
  Vec3 box_max = Vec3::Zero();
  std::string note;
};

struct AnimationBody {
  std::string name;
  std::vector<AnimationPart> parts;
  Mat3 I_G_B = Mat3::Identity();  // inertia about the COM, body axes, kg m^2: for L
  double extent = 1.0;            // m: radius of a sphere about the COM holding every part
};

// A fixed plane a body touches (a contact's ground or ramp).
struct AnimationPlane {
  std::string name;             // the first contact's with it
  Vec3 point_W = Vec3::Zero();  // a point of the plane, m
  Vec3 normal_W = Vec3::UnitZ();
};

// A joint, drawn where it holds its second body: a pivot's point, a hinge's or a slider's axis,
// and the link from the point to that body's COM when the point lies outside the body (a point
// mass on a massless link).
struct AnimationJoint {
  std::string name;
  std::string type;                // "ball", "hinge", "prismatic", "fixed"
  std::size_t body = 0;            // the body it rides with: its second
  Vec3 point_GJ_B = Vec3::Zero();  // the joint point from that body's COM, its axes, m
  Vec3 axis_B = Vec3::UnitZ();     // a hinge's or slider's axis, its axes
};

// A distance joint's massless rod, drawn as a line between its ends, each fixed to its body.
struct AnimationRod {
  std::string name;
  int body_a = -1, body_b = -1;  // -1: ground
  Vec3 end_a = Vec3::Zero();     // from body_a's COM, its axes (ground: world), m
  Vec3 end_b = Vec3::Zero();     // from body_b's COM, its axes (ground: world), m
};

struct AnimationScene {
  std::string name;  // the scenario's: the page's title
  std::vector<AnimationBody> bodies;
  std::vector<AnimationPlane> planes;  // one per distinct plane of the contacts
  std::vector<AnimationJoint> joints;  // but the rods
  std::vector<AnimationRod> rods;
  bool planar = false;  // seen from +z, y up, as the chapter draws it
};

// The scene of a scenario: every body's parts (a single shape is one part), meshes loaded, the
// contacts' planes (each once: several bodies may touch one ramp), and the joints.
AnimationScene make_animation_scene(const Scenario& scenario);

// The output rows, kept in memory for the page.
class RecordedTrajectory final : public RowSink {
 public:
  explicit RecordedTrajectory(std::size_t body_count) : body_count_(body_count) {}
  // From now on each row's values of these plots' columns are kept too (write_row).
  void record_plots(const ColumnLayout& layout, std::vector<AnimationPlot> plots);
  void record(double t, std::span<const BodyState> states, const SystemQuantities& q);
  void write_row(const OutputRow& row) override;
  std::size_t rows() const { return t_.size(); }
  std::size_t body_count() const { return body_count_; }
  double t(std::size_t row) const { return t_[row]; }
  const BodyState& state(std::size_t row, std::size_t body) const {
    return states_[row * body_count_ + body];
  }
  const SystemQuantities& quantities(std::size_t row) const { return quantities_[row]; }
  const std::vector<AnimationPlot>& plots() const { return plots_; }
  // Row after row, each plot's columns in turn.
  const std::vector<double>& plot_values() const { return plot_values_; }

 private:
  std::size_t body_count_;
  std::vector<AnimationPlot> plots_;
  std::vector<std::function<double(const OutputRow&)>> plot_columns_;
  std::vector<double> plot_values_;
  std::vector<double> t_;
  std::vector<BodyState> states_;  // row-major: rows x bodies
  std::vector<SystemQuantities> quantities_;
};

// Writes the page under a temporary name beside `path` and renames it into place. Throws
// std::runtime_error naming the path if it cannot be written, or std::invalid_argument if the
// scene and the rows disagree on the number of bodies.
// `events` (in time order) are marked on the plots' time axes.
void write_animation_html(const std::filesystem::path& path, const AnimationScene& scene,
                          const RecordedTrajectory& rows,
                          std::span<const AnimationEvent> events = {});

// For the tests: the JSON string literal of `text` (with quotes), safe inside <script>.
std::string json_string(std::string_view text);

}  // namespace tumble
