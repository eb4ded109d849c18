// A round body (a disk or ring, a cylinder or tube, a cone, a torus, a capsule; round_contact.hpp)
// on a plane (contact_pair.hpp): it touches at a rim point (a cone's apex, a capsule's cap), along
// its side or on a face, tips from the side or a face onto a rim point where the centre of
// pressure leaves it, and rolls on a rim point that runs round the rim (on a cap, as a sphere).
#include <algorithm>
#include <array>
#include <cmath>

#include "tumble/contact/contact_pairs.hpp"
#include "tumble/contact/round_contact.hpp"

namespace tumble {

namespace {

// A rim point's direction is kept up with, step by step, where its tilt's sine is below this.
constexpr double kRimKeptUpTilt = 1e-2;

// Which end of a round surface is the lower along -n_B (0: A, 1: B; B of equals), and the
// direction of its lowest rim point.
int lower_end(const RoundEnds& ends, const Vec3& n_B, Vec3& u_B) {
  double projected = 0.0;
  u_B = lowest_rim_direction(ends, n_B, projected);
  if (ends.one_rim) return 1;
  return rim_point(ends, 0, u_B).dot(n_B) < rim_point(ends, 1, u_B).dot(n_B) ? 0 : 1;
}

class RoundOnPlane final : public ContactPair {
 public:
  Vec3 lowest_point_B(const ContactSurface& surface, const Vec3& n_B) const override {
    const RoundEnds ends = round_ends(surface);
    Vec3 u = Vec3::UnitX();
    const int end = lower_end(ends, n_B, u);
    return surface_point(ends, end, u, n_B);
  }
  Vec3 lowest_point_rate_B(const ContactSurface& surface, const Vec3& n_B,
                           const Vec3& omega_B) const override {
    const Vec3 n_rate_B = n_B.cross(omega_B);
    const RoundEnds ends = round_ends(surface);
    Vec3 u = Vec3::UnitX();
    const double r = ends.radius[static_cast<std::size_t>(lower_end(ends, n_B, u))];
    double projected = 0.0;
    lowest_rim_direction(ends, n_B, projected);
    if (projected == 0.0 || r == 0.0) return surface_point_rate(ends, Vec3::Zero(), n_B, omega_B);
    // u = -P n / |P n| with P the projection on the ends' plane: u' = -(1 - u u^T) P n' / |P n|.
    const Vec3 projected_rate = in_ends_plane(ends, n_rate_B);
    const Vec3 u_rate = -(projected_rate - u * u.dot(projected_rate)) / projected;
    return surface_point_rate(ends, r * u_rate, n_B, omega_B);
  }
  double size(const ContactSurface& surface) const override {
    double size = 0.0;
    const RoundEnds ends = round_ends(surface);
    for (std::size_t k = 0; k < 2; ++k) {
      // The farthest rim point from the COM: on the body's own axis, the rim's centre is on the
      // rim's axis; a composite's part may have it anywhere, up to |c| + r. A torus's surface
      // reaches its tube's radius beyond.
      size = std::max(size, (ends.turned ? ends.centre_B[k].norm() + ends.radius[k]
                                         : std::hypot(ends.radius[k], ends.centre_B[k].norm())) +
                                ends.tube);
    }
    for (const Vec3& p : surface.vertices) size = std::max(size, p.norm());  // a cone's apex
    return size;
  }
  double time_to_reach_depth(const PlaneContact& contact, const SurfaceMotion& motion,
                             double turning, double depth) const override {
    const RoundEnds ends = round_ends(contact.surface);
    double t = kNever;
    for (std::size_t k = ends.one_rim ? 1 : 0; k < 2; ++k) {
      // A cone's apex; a capsule's cap, a sphere about that point (turning about it moves no
      // point of the sphere lower).
      t = std::min(t, ends.radius[k] == 0.0
                          ? point_time_to_depth(contact, motion, ends.centre_B[k], turning,
                                                depth - ends.tube)
                          : circle_time_to_depth(contact, motion, ends.centre_B[k], ends.axes_B,
                                                 ends.radius[k], turning, depth - ends.tube));
    }
    return t;
  }

  std::string resting_point(const ContactSurface& surface, const Vec3& n_B, const SupportPoint&,
                            double within, FunctionRef<double(const Vec3&)> height_of,
                            ContactPoint& point) const override {
    const RoundEnds ends = round_ends(surface);
    double tilt = 0.0;
    const Vec3 u_B = lowest_rim_direction(ends, n_B, tilt);
    // A cone on its apex, the base's rim off the plane (a top, upright or leaning): a point of
    // the body, whatever the tilt.
    const bool apex_down = ends.radius[0] == 0.0 && !(ends.tube > 0.0) && !ends.one_rim &&
                           height_of(ends.centre_B[0]) <= within;
    if (apex_down && height_of(surface_point(ends, 1, u_B, n_B)) > within) {
      point.kind = ContactPoint::Kind::Material;
      point.p_B = ends.centre_B[0];
      return {};
    }
    const bool has_faces = ends.radius[0] > 0.0 || ends.radius[1] > 0.0;  // not a capsule
    if (has_faces && tilt <= 1e-9) {
      return "the body lies flat on an end face, where a small tilt moves the plane's force to "
             "its rim: no linearisation";
    }
    int ends_down = 0, end = 0;
    for (int k = ends.one_rim ? 1 : 0; k < 2; ++k) {
      if (height_of(surface_point(ends, k, u_B, n_B)) <= within) {
        ++ends_down;
        end = k;
      }
    }
    if (ends_down != 1) {
      return "the body rests along a line of its side, where a small tilt moves the plane's "
             "force to one end: no linearisation";
    }
    const auto k = static_cast<std::size_t>(end);
    point.p_B = ends.centre_B[k];
    if (ends.radius[k] == 0.0 && ends.tube > 0.0) {  // a capsule's cap: a sphere's lowest point
      point.kind = ContactPoint::Kind::Lowest;
      point.radius = ends.tube;
      return {};
    }
    point.axis_B = ends.axes_B.col(2);
    point.radius = ends.radius[k];
    point.tube = ends.tube;
    point.kind = point.radius > 0.0 ? ContactPoint::Kind::Rim : ContactPoint::Kind::Material;
    return {};
  }

  bool calc_part_points(PairView& v, const Vec3& omega_B) const override {
    const ContactStatus& status = v.status;
    if (status.round_part == RoundPart::None) return false;
    ContactNow& now = v.now;
    const RoundEnds ends = round_ends(v.surface());
    const RoundPartPoints part =
        round_part_points(ends, status.round_part, now.n_B, omega_B, status.rim_direction_B);
    now.normal_points_B = part.points_B;
    now.normal_point_rates_B = part.rates_B;
    now.normal_point_count = part.count;
    now.reference_B = part.reference_B;
    now.reference_rate_B = part.reference_rate_B;
    now.spin_radius = part.spin_radius;
    // Touchdown watches what may land next, on one end's rim point (a cone's apex): the other
    // end's lowest rim point, or this end's face: its highest rim point, 2 r sin(tilt) above the
    // plane, lands with the rest of the rim within the landing height of it. (Nearer flat, a rim
    // point that rolls or slides runs round the rim ever faster, as 1 / sin(tilt): Euler's
    // disk.) On the side or a face: nothing (they tip onto a rim point first).
    now.support.p_GC_B.setZero();
    now.support.height = 1.0;  // nothing left to land
    if (!is_end(status.round_part)) return true;
    const int end = end_of(status.round_part);
    const double radius = ends.radius[static_cast<std::size_t>(end)];
    // The rim point's direction u (part.points_B[0] = C + r u, a torus's less its tube along
    // n): the lowest point, to ~1e-12.
    const Vec3& centre = ends.centre_B[static_cast<std::size_t>(end)];
    const Vec3 rim =
        ends.tube > 0.0 ? Vec3(part.points_B[0] + ends.tube * now.n_B) : part.points_B[0];
    const Vec3 u = radius > 0.0 ? Vec3((rim - centre) / radius)
                                : rim_direction(ends, now.n_B, status.rim_direction_B);
    if (radius > 0.0) {
      now.support.p_GC_B = surface_point(ends, end, -u, now.n_B);
      now.support.height = 2.0 * radius * tilt_sine(ends, now.n_B) - status.landing_height;
    }
    if (ends.one_rim) return true;
    const Vec3 other = surface_point(ends, 1 - end, u, now.n_B);
    const double other_height = v.height(other);
    if (radius == 0.0 || other_height <= now.support.height) {
      now.support.p_GC_B = other;
      now.support.height = other_height;
    }
    return true;
  }

  void for_each_landing_point(const PairView& v,
                              FunctionRef<void(const Vec3&)> watch) const override {
    const RoundEnds ends = round_ends(v.surface());
    double projected = 0.0;
    const Vec3 u = lowest_rim_direction(ends, v.now.n_B, projected);
    for (int k = ends.one_rim ? 1 : 0; k < 2; ++k) watch(surface_point(ends, k, u, v.now.n_B));
  }

  double support_margin(const PairView& v, int& side) const override {
    const ContactNow& now = v.now;
    if (v.status.round_part == RoundPart::None) {
      side = -1;
      return now.normal_force;
    }
    return round_support_margin(v.surface(), v.status.round_part, now.normal_points_B,
                                now.reference_B, now.n_B, now.normal_force, now.moment_about_O_B,
                                side);
  }

  const char* part_name(const PairView& v) const override {
    const RoundPart part = v.status.round_part;
    return part != RoundPart::None ? round_part_name(v.surface(), part) : nullptr;
  }

  const char* end_name(const PairView& v, int end) const override {
    return round_part_name(v.surface(), end == 0 ? RoundPart::EndA : RoundPart::EndB);
  }

  bool find_touching_part(PairView& v, double within, bool resting) const override {
    ContactStatus& status = v.status;
    const RoundEnds ends = round_ends(v.surface());
    const Vec3 n_B = v.n_B();
    const Vec3 omega_B = v.motion.velocity.head<3>();
    const auto touches = [&](const Vec3& p_B) {
      const double height = v.height(p_B);
      if (height > within) return false;
      const double speed = v.normal_speed(p_B);
      return resting ? speed <= status.slip_zero : v.lands_with(height, speed);
    };
    // The rims' lowest points; with a whole rim within `within` (a face nearly flat), the rim
    // point moving down the fastest, which leads if the face tilts: a point C + r e has normal
    // speed v_C.n + r e.(n x omega).
    double projected = 0.0;
    Vec3 u = lowest_rim_direction(ends, n_B, projected);
    const double widest = std::max(ends.radius[0], ends.radius[1]);
    if (2.0 * widest * projected <= within) {
      const Vec3 tilting = n_B.cross(omega_B);
      const Vec3 in_plane = in_ends_plane(ends, tilting);
      u = in_plane.norm() > 0.0 ? Vec3(-in_plane.normalized()) : status.rim_direction_B;
    }
    status.rim_direction_B = u;
    // Per end: its lowest rim point touches; its whole face does (the far rim point too).
    std::array<bool, 2> low{}, face{};
    for (int k = ends.one_rim ? 1 : 0; k < 2; ++k) {
      const auto e = static_cast<std::size_t>(k);
      low[e] = touches(surface_point(ends, k, u, n_B));
      face[e] = low[e] && ends.radius[e] > 0.0 && touches(surface_point(ends, k, -u, n_B));
    }
    if (face[1]) {
      status.round_part = RoundPart::FaceB;
    } else if (face[0]) {
      status.round_part = RoundPart::FaceA;
    } else if (low[0] && low[1]) {
      status.round_part = RoundPart::Side;
    } else if (low[0] || low[1]) {
      status.round_part = low[0] ? RoundPart::EndA : RoundPart::EndB;
    } else if (resting) {
      status.round_part = RoundPart::None;
    } else {
      // A landing located to round-off is at the plane: at least the lower end.
      const bool a_lower =
          !ends.one_rim && rim_point(ends, 0, u).dot(n_B) < rim_point(ends, 1, u).dot(n_B);
      status.round_part = a_lower ? RoundPart::EndA : RoundPart::EndB;
    }
    return status.round_part != RoundPart::None;
  }

  void find_settled_part(PairView& v) const override {
    // What landed with it: its points within the landing height that the plastic impulse stopped
    // (a face lands with its far side that high, not yet at the plane).
    find_touching_part(v, v.status.landing_height, false);
  }

  bool keep_unbounced_part(PairView& v) const override {
    // The part's points that did not bounce off stay on the plane.
    return find_touching_part(v, v.status.touching_height, true);
  }

  bool settle_on_candidates(PairView& v, SettleTry settle) const override {
    // The part; if that is inconsistent, the parts it may tip onto: the side onto either end's
    // rim point, a face onto the rim point where its CoP left.
    ContactStatus& status = v.status;
    const RoundEnds ends = round_ends(v.surface());
    v.touching.clear();  // the round body's left-out points are named per candidate
    const std::array<SurfacePoint, 2> ends_low = end_points(v);
    const auto one = [](const SurfacePoint& p) { return std::span<const SurfacePoint>(&p, 1); };
    const RoundPart part = status.round_part;
    switch (part) {
      case RoundPart::Side:
        if (settle({})) return true;
        status.round_part = RoundPart::EndA;  // end B's rim point lifts
        if (settle(one(ends_low[1]))) return true;
        status.round_part = RoundPart::EndB;  // end A's lifts
        return settle(one(ends_low[0]));
      case RoundPart::FaceA:
      case RoundPart::FaceB: {
        if (settle({})) return true;
        tip(v, 0);  // onto the rim where the CoP went (the face's forces, in v.now)
        const SurfacePoint centre{
            on_surface(ends, ends.centre_B[static_cast<std::size_t>(end_of(part))], v.n_B())};
        return settle(one(centre));
      }
      case RoundPart::EndA:
      case RoundPart::EndB: {
        // The other end, if it is at the plane too and not leaving it, must not go into it; if
        // it would, the body lies on its side (a cone whose rim has landed while its apex, at
        // the plane, comes down: on its rim alone no mode holds, and it would land again every
        // nanosecond). One that an impact sent off (the far rim of a can that landed it while
        // rocking on the near one) leaves, whatever its acceleration.
        SurfacePoint other;
        const bool at_plane = other_end_B(v, other) &&
                              v.height(other.p_B) <= status.touching_height &&
                              v.normal_speed(other.p_B) <= status.slip_zero;
        if (settle(at_plane ? one(other) : std::span<const SurfacePoint>())) return true;
        if (!at_plane) return false;
        status.round_part = RoundPart::Side;
        return settle({});
      }
      default:
        return settle({});
    }
  }

  bool can_tip(const PairView&) const override { return true; }
  bool tip_at_impact(PairView& v, int side) const override {
    if (side < 0) return false;
    tip(v, side);
    return true;
  }
  bool tip_on_support(PairView& v, int side, bool) const override {
    if (side < 0 || v.status.round_part == RoundPart::None || !(v.now.normal_force > 0.0)) {
      return false;
    }
    tip(v, side);
    return true;
  }

  bool anchored(const PairView& v) const override {
    const RoundPart part = v.status.round_part;
    if (is_face(part)) return true;
    // A point fixed in the body: a cone's apex (an end of radius 0 that no tube sweeps; a
    // capsule's cap rolls).
    const RoundEnds ends = round_ends(v.surface());
    return part == RoundPart::EndA && ends.radius[0] == 0.0 && !(ends.tube > 0.0);
  }

  bool other_end_B(const PairView& v, SurfacePoint& other) const override {
    const ContactStatus& status = v.status;
    const RoundEnds ends = round_ends(v.surface());
    if (ends.one_rim || !is_end(status.round_part)) return false;
    other = end_points(v)[status.round_part == RoundPart::EndA ? 1 : 0];
    return true;
  }

  bool projects_along_normal(const PairView& v) const override {
    // A disk's, ring's or cylinder's rim point (a capsule's cap's lowest point) is its support
    // point (not a cone's: its apex and its base's rim are two ends of one line).
    return v.surface().kind != ContactSurface::Kind::Cone && is_end(v.status.round_part);
  }

  double point_height(const PairView& v) const override {
    const RoundPart part = v.status.round_part;
    if (part == RoundPart::None) return ContactPair::point_height(v);
    // The rim point it touches at (not the other end's, which may be as low).
    const RoundEnds ends = round_ends(v.surface());
    const Vec3 u = rim_direction(ends, v.n_B(), v.status.rim_direction_B);
    return v.height(surface_point(ends, end_of(part), u, v.n_B()));
  }

  bool follows_direction(const PairView& v) const override {
    // Only near flat does the lean towards the last direction count (round_contact.hpp); above
    // kRimKeptUpTilt it moves the rim point by less than 1e-10 of the radius, so the direction is
    // kept up with only there (judged by the last evaluation's normal in body axes).
    const Vec3& n_B = v.now.n_B;
    return holds_rim_point(v.surface(), v.status.round_part) &&
           tilt_sine(round_ends(v.surface()), n_B) < kRimKeptUpTilt;
  }
  void follow_direction(PairView& v) const override {
    v.status.rim_direction_B =
        rim_direction(round_ends(v.surface()), v.now.n_B, v.status.rim_direction_B);
  }

 private:
  // Each end's lowest rim point, which moves over the body as the body turns (not as it spins
  // about its axis), and its rate.
  static std::array<SurfacePoint, 2> end_points(const PairView& v) {
    const RoundEnds ends = round_ends(v.surface());
    const Vec3 n_B = v.n_B(), omega_B = v.motion.velocity.head<3>();
    Vec3 u = Vec3::UnitX(), u_rate = Vec3::Zero();
    rim_direction_and_rate(ends, n_B, omega_B, v.status.rim_direction_B, u, u_rate);
    return {SurfacePoint{surface_point(ends, 0, u, n_B),
                         surface_point_rate(ends, ends.radius[0] * u_rate, n_B, omega_B)},
            SurfacePoint{surface_point(ends, 1, u, n_B),
                         surface_point_rate(ends, ends.radius[1] * u_rate, n_B, omega_B)}};
  }

  // A round body on its side or a face tips onto the end of the side (side 0: end A's rim point,
  // 1: end B's), or the face's rim point where the CoP leaves it (after a solve).
  static void tip(PairView& v, int side) {
    ContactStatus& status = v.status;
    const ContactNow& now = v.now;
    if (status.round_part == RoundPart::Side) {
      status.round_part = side == 0 ? RoundPart::EndA : RoundPart::EndB;
    } else if (is_face(status.round_part)) {
      status.rim_direction_B = face_tip_direction(round_ends(v.surface()), now.n_B,
                                                  now.moment_about_O_B, status.rim_direction_B);
      status.round_part = end_of(status.round_part) == 0 ? RoundPart::EndA : RoundPart::EndB;
    }
  }
};

}  // namespace

const ContactPair& round_on_plane() {
  static const RoundOnPlane pair;
  return pair;
}

}  // namespace tumble
