#include "tumble/contact/contact_feature.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

namespace {

// Points of the plane closer than this fraction of the feature's extent are one point, and a
// turn smaller than it (relative to the sides' lengths) is no turn: a box's face has its four
// corners exactly, and a mesh's coplanar vertices lie within round-off of each other's plane.
constexpr double kSameSpot = 1e-9;

double cross_2d(const Vec3& o, const Vec3& a, const Vec3& b, const Vec3& n) {
  return n.dot((a - o).cross(b - o));
}

// The integral of the distance from the origin over the triangle (0, A, B), all in the plane:
// in polar coordinates about the origin the far side is at r = h / cos(phi), so the integral is
// int (h / cos)^3 / 3 dphi, in closed form in s, the position along AB from the foot of the
// perpendicular.
double distance_integral(const Vec3& A, const Vec3& B) {
  const Vec3 d = B - A;
  const double length = d.norm();
  if (length == 0.0) return 0.0;
  const Vec3 e = d / length;
  const Vec3 foot = A - e * A.dot(e);
  const double h = foot.norm();
  if (h == 0.0) return 0.0;
  const auto P = [h](double s) {
    return (h * s * std::sqrt(h * h + s * s) + h * h * h * std::asinh(s / h)) / 6.0;
  };
  return std::abs(P(B.dot(e)) - P(A.dot(e)));
}

void finish_sides(std::span<const Vec3> vertices_B, const Vec3& n_B, ContactFeature& f) {
  f.inward_B.clear();
  const int count = f.size();
  const auto at = [&](int j) {
    return vertices_B[static_cast<std::size_t>(f.polygon[static_cast<std::size_t>(j)])];
  };
  if (count == 1) {
    f.normal_points = {f.polygon[0], 0, 0};
    f.normal_point_count = 1;
    f.reference_B = at(0);
    f.spin_radius = 0.0;
    return;
  }
  if (count == 2) {
    const Vec3 e = (at(1) - at(0)).normalized();
    f.inward_B.push_back(e);
    f.inward_B.push_back(-e);
    f.normal_points = {f.polygon[0], f.polygon[1], 0};
    f.normal_point_count = 2;
    f.reference_B = 0.5 * (at(0) + at(1));
    f.spin_radius = 0.25 * (at(1) - at(0)).norm();  // mean |x| over [-L/2, L/2]
    return;
  }
  // A face: area centroid, mean distance from it, inward side normals.
  double area = 0.0;
  Vec3 moment = Vec3::Zero();
  for (int j = 1; j + 1 < count; ++j) {
    const double a = 0.5 * cross_2d(at(0), at(j), at(j + 1), n_B);
    area += a;
    moment += a * (at(0) + at(j) + at(j + 1)) / 3.0;
  }
  f.reference_B = moment / area;
  double distance = 0.0;
  for (int j = 0; j < count; ++j) {
    const Vec3 A = at(j) - f.reference_B, B = at((j + 1) % count) - f.reference_B;
    distance += distance_integral(A - n_B * n_B.dot(A), B - n_B * n_B.dot(B));
    f.inward_B.push_back(n_B.cross(at((j + 1) % count) - at(j)).normalized());
  }
  f.spin_radius = distance / area;
  // Three vertices spanning the face: the first, the farthest from it, the farthest from their
  // line.
  int far = 1;
  for (int j = 2; j < count; ++j) {
    if ((at(j) - at(0)).squaredNorm() > (at(far) - at(0)).squaredNorm()) far = j;
  }
  int wide = far == 1 ? 2 : 1;
  for (int j = 1; j < count; ++j) {
    if (j == far) continue;
    if (std::abs(cross_2d(at(0), at(far), at(j), n_B)) >
        std::abs(cross_2d(at(0), at(far), at(wide), n_B))) {
      wide = j;
    }
  }
  f.normal_points = {f.polygon[0], f.polygon[static_cast<std::size_t>(far)],
                     f.polygon[static_cast<std::size_t>(wide)]};
  f.normal_point_count = 3;
}

}  // namespace

void plane_basis(const Vec3& n, Vec3& u, Vec3& v) {
  const Vec3 a = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  u = a.cross(n).normalized();
  v = n.cross(u);
}

bool ContactFeature::contains(int vertex) const {
  return std::find(polygon.begin(), polygon.end(), vertex) != polygon.end();
}

void reserve_feature(ContactFeature& feature, std::size_t vertex_count) {
  feature.polygon.reserve(3 * vertex_count + 4);  // the sort's copy and both chains
  feature.inward_B.reserve(vertex_count + 2);
}

void make_feature(std::span<const Vec3> vertices_B, std::span<const int> touching, const Vec3& n_B,
                  ContactFeature& feature) {
  Vec3 u, v;
  plane_basis(n_B, u, v);
  const auto point = [&](int i) { return vertices_B[static_cast<std::size_t>(i)]; };
  double extent = 0.0;
  for (const int i : touching) extent = std::max(extent, (point(i) - point(touching[0])).norm());
  const double same = kSameSpot * std::max(extent, 1e-300);

  // Andrew's monotone chain in the plane, on `polygon` as scratch (reserved: no allocation).
  std::vector<int>& hull = feature.polygon;
  hull.clear();
  feature.inward_B.clear();
  // The touching vertices sorted by (u, v), then the two chains after them.
  const std::size_t n = touching.size();
  hull.insert(hull.end(), touching.begin(), touching.end());
  std::sort(hull.begin(), hull.end(), [&](int a, int b) {
    const double ua = point(a).dot(u), ub = point(b).dot(u);
    if (ua != ub) return ua < ub;
    return point(a).dot(v) < point(b).dot(v);
  });
  // Build the hull after the sorted points, then move it to the front.
  const auto turns_left = [&](int o, int a, int b) {
    const double scale = (point(a) - point(o)).norm() * (point(b) - point(o)).norm();
    return cross_2d(point(o), point(a), point(b), n_B) > kSameSpot * scale;
  };
  std::size_t k = n;
  for (std::size_t pass = 0; pass < 2; ++pass) {
    const std::size_t start = k;
    for (std::size_t s = 0; s < n; ++s) {
      const int p = hull[pass == 0 ? s : n - 1 - s];
      if (k > start && (point(p) - point(hull[k - 1])).norm() <= same) continue;
      while (k >= start + 2 && !turns_left(hull[k - 2], hull[k - 1], p)) {
        hull.pop_back();
        --k;
      }
      hull.push_back(p);
      ++k;
    }
    if (k > start + 1) {
      hull.pop_back();  // the chain's last point starts the other chain
      --k;
    }
  }
  hull.erase(hull.begin(), hull.begin() + static_cast<std::ptrdiff_t>(n));
  // A single point, or an edge whose ends the two chains both hold.
  if (hull.empty()) hull.push_back(touching[0]);
  if (hull.size() == 2 && (point(hull[0]) - point(hull[1])).norm() <= same) hull.pop_back();
  finish_sides(vertices_B, n_B, feature);
}

void tip_onto_side(std::span<const Vec3> vertices_B, int side, const Vec3& n_B,
                   ContactFeature& feature) {
  const int count = feature.size();
  const int first = feature.polygon[static_cast<std::size_t>(side)];
  if (count == 2) {
    feature.polygon.assign(1, first);
  } else {
    const int second = feature.polygon[static_cast<std::size_t>((side + 1) % count)];
    feature.polygon.assign({first, second});
  }
  finish_sides(vertices_B, n_B, feature);
}

double support_margin(const ContactFeature& feature, std::span<const Vec3> vertices_B,
                      const Vec3& n_B, double N, const Vec3& M_O_B, int& side) {
  side = -1;
  if (feature.size() < 2) return N;
  // N (c - O) = n x M_O for the resultant's CoP c: the normal forces' moment about O lies in
  // the plane, and n x (r x n) = r for r in it.
  const Vec3 N_c = n_B.cross(M_O_B) + N * feature.reference_B;
  double least = 0.0;
  for (int j = 0; j < static_cast<int>(feature.inward_B.size()); ++j) {
    const Vec3& a =
        vertices_B[static_cast<std::size_t>(feature.polygon[static_cast<std::size_t>(j)])];
    const double margin = feature.inward_B[static_cast<std::size_t>(j)].dot(N_c - N * a);
    if (side < 0 || margin < least) {
      least = margin;
      side = j;
    }
  }
  return least;
}

}  // namespace tumble
