// A polyhedron (a box, a plate, a mesh's convex hull) on a plane (contact_pair.hpp): it touches
// on a feature of its vertices (one vertex, an edge or a face, contact_feature.hpp), tips onto a
// smaller feature where the centre of pressure leaves it, and sticks held at an anchor. On a body
// a joint holds, each of its feature's points is held on its own.
#include <fmt/core.h>

#include <algorithm>
#include <array>

#include "tumble/contact/contact_feature.hpp"
#include "tumble/contact/contact_pairs.hpp"

namespace tumble {

namespace {

const char* feature_name(int size) {
  return size == 1 ? "a vertex" : size == 2 ? "an edge" : "a face";
}

class PolyhedronOnPlane final : public ContactPair {
 public:
  Vec3 lowest_point_B(const ContactSurface& surface, const Vec3& n_B) const override {
    return surface.vertices[static_cast<std::size_t>(lowest_vertex(surface, n_B))];
  }
  Vec3 lowest_point_rate_B(const ContactSurface&, const Vec3&, const Vec3&) const override {
    return Vec3::Zero();  // a vertex: fixed in the body
  }
  double size(const ContactSurface& surface) const override {
    double size = 0.0;
    for (const Vec3& p : surface.vertices) size = std::max(size, p.norm());
    return size;
  }
  double time_to_reach_depth(const PlaneContact& contact, const SurfaceMotion& motion,
                             double turning, double depth) const override {
    double t = kNever;
    for (const Vec3& p : contact.surface.vertices) {
      t = std::min(t, point_time_to_depth(contact, motion, p, turning, depth));
    }
    return t;
  }

  std::string resting_point(const ContactSurface& surface, const Vec3&, const SupportPoint& lowest,
                            double within, FunctionRef<double(const Vec3&)> height_of,
                            ContactPoint& point) const override {
    int count = 0;
    for (const Vec3& vertex : surface.vertices) count += height_of(vertex) <= within ? 1 : 0;
    if (count > 1) {
      return fmt::format(
          "the body rests on an edge or a face ({} vertices on the plane), where a small tilt "
          "moves the plane's force to one side: no linearisation; balance it on one vertex, or "
          "remove the contact",
          count);
    }
    point.kind = ContactPoint::Kind::Material;
    point.p_B = lowest.p_GC_B;
    return {};
  }

  bool held_point_by_point() const override { return true; }

  bool calc_part_points(PairView& v, const Vec3&) const override {
    const ContactFeature& feature = v.status.feature;
    if (feature.size() == 0) return false;
    // On a feature; touchdown watches its lowest vertex not already touching.
    const ContactSurface& surface = v.surface();
    ContactNow& now = v.now;
    int lowest = -1;
    double lowest_depth = 0.0;
    for (std::size_t i = 0; i < surface.vertices.size(); ++i) {
      if (feature.contains(static_cast<int>(i))) continue;
      const double depth = surface.vertices[i].dot(now.n_B);
      if (lowest < 0 || depth < lowest_depth) {
        lowest = static_cast<int>(i);
        lowest_depth = depth;
      }
    }
    now.support.p_GC_B =
        lowest >= 0 ? surface.vertices[static_cast<std::size_t>(lowest)] : Vec3::Zero();
    now.support.height = lowest >= 0 ? v.height(now.support.p_GC_B)
                                     : 1.0;  // every vertex touches: nothing left to land
    now.reference_B = feature.reference_B;
    now.reference_rate_B.setZero();
    now.normal_point_count = feature.normal_point_count;
    for (int k = 0; k < feature.normal_point_count; ++k) {
      now.normal_points_B[static_cast<std::size_t>(k)] = surface.vertices[static_cast<std::size_t>(
          feature.normal_points[static_cast<std::size_t>(k)])];
    }
    return true;
  }

  void for_each_landing_point(const PairView& v,
                              FunctionRef<void(const Vec3&)> watch) const override {
    for (const Vec3& p : v.surface().vertices) watch(p);
  }

  double support_margin(const PairView& v, int& side) const override {
    return tumble::support_margin(v.status.feature, v.surface().vertices, v.now.n_B,
                                  v.now.normal_force, v.now.moment_about_O_B, side);
  }

  const char* part_name(const PairView& v) const override {
    const int size = v.status.feature.size();
    return size > 0 ? feature_name(size) : nullptr;
  }

  bool find_touching_part(PairView& v, double within, bool resting) const override {
    const ContactSurface& surface = v.surface();
    v.touching.clear();
    for (std::size_t i = 0; i < surface.vertices.size(); ++i) {
      const Vec3& p = surface.vertices[i];
      const double height = v.height(p);
      if (height > within) continue;
      const double speed = v.normal_speed(p);
      if (resting ? speed <= v.status.slip_zero : v.lands_with(height, speed)) {
        v.touching.push_back(static_cast<int>(i));
      }
    }
    if (v.touching.empty()) {
      if (resting) return false;
      // At least the lowest vertex (a landing located to round-off is at the plane).
      v.touching.push_back(lowest_vertex(surface, v.n_B()));
    }
    make_feature(surface.vertices, v.touching, v.now.n_B, v.status.feature);
    return true;
  }

  void find_settled_part(PairView& v) const override {
    // On everything now at the plane: which part carries it is the classification's to find
    // (the impulse's own centre may have left a vertex out that the forces need).
    find_touching_part(v, v.status.touching_height, false);
  }

  bool keep_unbounced_part(PairView& v) const override {
    // The feature's vertices that did not bounce off stay on the plane.
    const ContactSurface& surface = v.surface();
    v.touching.clear();
    for (const int i : v.status.feature.polygon) {
      const Vec3& p = surface.vertices[static_cast<std::size_t>(i)];
      if (v.normal_speed(p) <= v.status.slip_zero) v.touching.push_back(i);
    }
    if (v.touching.empty()) return false;
    make_feature(surface.vertices, v.touching, v.n_B(), v.status.feature);
    return true;
  }

  bool settle_on_candidates(PairView& v, SettleTry settle) const override {
    // The candidates, in order: the whole feature; a face's edges; its (or an edge's) vertices;
    // apart. The first whose forces are consistent is the one (for these few, enumerating them
    // solves the complementarity problem exactly).
    ContactStatus& status = v.status;
    std::vector<int>& touching = v.touching;
    touching.assign(status.feature.polygon.begin(), status.feature.polygon.end());
    const int k = static_cast<int>(touching.size());
    const int edges = k >= 3 ? k : 0;
    const int vertices = k >= 2 ? k : 0;
    const Vec3 n_B = v.n_B();
    for (int candidate = 0; candidate <= edges + vertices; ++candidate) {
      if (candidate > 0) {
        std::array<int, 2> pick{};
        std::size_t count = 1;
        if (candidate <= edges) {
          pick = {touching[static_cast<std::size_t>(candidate - 1)],
                  touching[static_cast<std::size_t>(candidate % k)]};
          count = 2;
        } else {
          pick[0] = touching[static_cast<std::size_t>(candidate - 1 - edges)];
        }
        make_feature(v.surface().vertices, std::span<const int>(pick.data(), count), n_B,
                     status.feature);
      }
      if (settle({})) return true;
    }
    return false;
  }

  bool can_tip(const PairView& v) const override { return v.status.feature.size() >= 2; }
  bool tip_at_impact(PairView& v, int side) const override {
    tip_onto_side(v.surface().vertices, side, v.now.n_B, v.status.feature);
    return true;
  }
  void keep_landing_point(PairView& v, const Vec3& p_B) const override {
    const ContactSurface& surface = v.surface();
    for (const int i : v.status.feature.polygon) {
      if (surface.vertices[static_cast<std::size_t>(i)] == p_B) return;
    }
    for (std::size_t i = 0; i < surface.vertices.size(); ++i) {
      if (surface.vertices[i] != p_B) continue;
      const int vertex = static_cast<int>(i);
      make_feature(surface.vertices, std::span<const int>(&vertex, 1), v.now.n_B, v.status.feature);
      return;
    }
  }
  bool tip_on_support(PairView& v, int side, bool still_presses) const override {
    if (v.status.feature.size() < 2 || !still_presses) return false;
    tip_onto_side(v.surface().vertices, side, v.now.n_B, v.status.feature);
    return true;
  }
  bool drop_point(PairView& v, const Vec3& p_B) const override {
    const ContactSurface& surface = v.surface();
    v.touching.clear();
    for (const int i : v.status.feature.polygon) {
      if (surface.vertices[static_cast<std::size_t>(i)] != p_B) v.touching.push_back(i);
    }
    if (v.touching.empty()) return false;
    make_feature(surface.vertices, v.touching, v.now.n_B, v.status.feature);
    return true;
  }
  bool anchored(const PairView&) const override { return true; }
  bool projects_along_normal(const PairView&) const override { return false; }
};

}  // namespace

const ContactPair& polyhedron_on_plane() {
  static const PolyhedronOnPlane pair;
  return pair;
}

}  // namespace tumble
