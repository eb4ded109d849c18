// A sphere or a shell on a plane (contact_pair.hpp): it touches at its lowest point, which moves
// over it as it turns, and has no part to settle, tip or stick on. Its centre is the body's COM,
// or, a composite's sphere part, a point fixed in the body (centre_B); the sphere at the COM keeps
// its own, simpler expressions (the same numbers, to the sign of a zero).
#include "tumble/contact/contact_pairs.hpp"

namespace tumble {

namespace {

class SphereOnPlane final : public ContactPair {
 public:
  Vec3 lowest_point_B(const ContactSurface& surface, const Vec3& n_B) const override {
    if (surface.centre_B.isZero(0.0)) return -surface.radius * n_B;
    return surface.centre_B - surface.radius * n_B;
  }
  Vec3 lowest_point_rate_B(const ContactSurface& surface, const Vec3& n_B,
                           const Vec3& omega_B) const override {
    return -surface.radius * n_B.cross(omega_B);
  }
  double size(const ContactSurface& surface) const override {
    return surface.centre_B.norm() + surface.radius;
  }
  double time_to_reach_depth(const PlaneContact& contact, const SurfaceMotion& motion,
                             double turning, double depth) const override {
    // The lowest point is the centre's less r: turning about the centre moves none lower.
    const ContactSurface& surface = contact.surface;
    if (surface.centre_B.isZero(0.0)) {
      return centre_time_to_depth(contact, motion, surface.radius, turning, depth);
    }
    return point_time_to_depth(contact, motion, surface.centre_B, turning, depth - surface.radius);
  }

  std::string resting_point(const ContactSurface& surface, const Vec3&, const SupportPoint&, double,
                            FunctionRef<double(const Vec3&)>, ContactPoint& point) const override {
    point.kind = ContactPoint::Kind::Lowest;
    point.p_B = surface.centre_B;
    point.radius = surface.radius;
    return {};
  }

  // The body's turning moves the lowest point only as it moves the centre.
  double turning_reach(const ContactSurface& surface) const override {
    return surface.centre_B.norm();
  }
  bool calc_part_points(PairView&, const Vec3&) const override { return false; }
  void for_each_landing_point(const PairView& v,
                              FunctionRef<void(const Vec3&)> watch) const override {
    watch(v.now.support.p_GC_B);
  }
  bool lands_while_touching() const override { return false; }
  double support_margin(const PairView& v, int& side) const override {
    side = -1;
    return v.now.normal_force;
  }
  const char* part_name(const PairView&) const override { return nullptr; }
  bool find_touching_part(PairView&, double, bool) const override { return true; }
  void find_settled_part(PairView&) const override {}
  bool keep_unbounced_part(PairView&) const override { return false; }
  bool settle_on_candidates(PairView& v, SettleTry settle) const override {
    v.touching.clear();  // no vertices to leave out
    return settle({});
  }
  bool can_tip(const PairView&) const override { return false; }
  bool tip_at_impact(PairView&, int) const override { return false; }
  bool tip_on_support(PairView&, int, bool) const override { return false; }
  bool anchored(const PairView&) const override { return false; }
  bool projects_along_normal(const PairView&) const override { return true; }
};

}  // namespace

const ContactPair& sphere_on_plane() {
  static const SphereOnPlane pair;
  return pair;
}

}  // namespace tumble
