#include "tumble/inertia/planar.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "tumble/inertia/mass_properties.hpp"

namespace tumble::planar {
namespace {

void require_positive(const char* what, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    std::ostringstream message;
    message << what << " must be > 0, got " << std::setprecision(6) << value;
    throw InertiaError(message.str());
  }
}

}  // namespace

// I_Gzz = int mu |d|^2 dA over each lamina or curve (chapter section 6.7.2, planar column).
double rod_about_center(double mass, double length) {
  require_positive("rod mass", mass);
  require_positive("rod length", length);
  return mass * length * length / 12.0;
}

double ring_about_center(double mass, double radius) {
  require_positive("ring mass", mass);
  require_positive("ring radius", radius);
  return mass * radius * radius;
}

double disk_about_center(double mass, double radius) {
  require_positive("disk mass", mass);
  require_positive("disk radius", radius);
  return mass * radius * radius / 2.0;
}

double plate_about_center(double mass, double a, double b) {
  require_positive("plate mass", mass);
  require_positive("plate side a", a);
  require_positive("plate side b", b);
  return mass * (a * a + b * b) / 12.0;
}

// Four rods of mass M/4 and length L, each with its centre L/2 from the frame's centre:
//   I = 4 [ (M/4) L^2 / 12 + (M/4) (L/2)^2 ] = M L^2 / 3   (chapter example 6, the Cubli).
double square_frame_about_center(double mass, double side) {
  require_positive("frame mass", mass);
  require_positive("frame side", side);
  const double rod_mass = mass / 4.0;
  return 4.0 * parallel_axis(rod_about_center(rod_mass, side), rod_mass, side / 2.0);
}

// I_O = I_G + M d^2, d the distance from the COM to the axis through O.
double parallel_axis(double inertia_about_com, double mass, double distance) {
  require_positive("mass", mass);
  if (!(inertia_about_com >= 0.0) || !std::isfinite(inertia_about_com)) {
    std::ostringstream message;
    message << "inertia about the COM must be >= 0, got " << std::setprecision(6)
            << inertia_about_com;
    throw InertiaError(message.str());
  }
  return inertia_about_com + mass * distance * distance;
}

}  // namespace tumble::planar
