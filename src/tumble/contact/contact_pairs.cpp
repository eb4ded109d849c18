// The one table of contact pairs (contact_pair.hpp): a body's surface, by its kind, against what
// it touches. A new surface kind adds a row; a body's surface touching another body's adds a
// column (and its pairs' files).
#include "tumble/contact/contact_pairs.hpp"

#include <array>
#include <cstddef>
#include <stdexcept>

namespace tumble {

const ContactPair& contact_pair(ContactSurface::Kind surface, TouchedSurface touched) {
  using Kind = ContactSurface::Kind;
  constexpr std::size_t kTouched = static_cast<std::size_t>(TouchedSurface::Plane) + 1;
  using Row = std::array<const ContactPair*, kTouched>;
  // Rows in the order of ContactSurface::Kind; columns in the order of TouchedSurface.
  static const std::array<Row, 6> table = {
      Row{&sphere_on_plane()},      // Sphere
      Row{&round_on_plane()},       // Circle
      Row{&round_on_plane()},       // Cylinder
      Row{&polyhedron_on_plane()},  // Polyhedron
      Row{&round_on_plane()},       // Cone
      Row{&round_on_plane()},       // Capsule (round_contact.hpp)
  };
  static_assert(static_cast<std::size_t>(Kind::Capsule) + 1 == 6, "a row for every surface kind");
  const ContactPair* pair =
      table[static_cast<std::size_t>(surface)][static_cast<std::size_t>(touched)];
  if (pair == nullptr) {
    throw std::logic_error("no contact pair for this surface; the scenario reader refuses it");
  }
  return *pair;
}

double ContactPair::point_height(const PairView& v) const {
  return support_point(v.contact, v.motion.r_G_W, v.motion.R_WB).height;
}

}  // namespace tumble
