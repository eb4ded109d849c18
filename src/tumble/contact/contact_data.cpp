#include "tumble/contact/contact_data.hpp"

#include <algorithm>

namespace tumble {

ContactData::ContactData(std::span<const PlaneContact> contacts, Eigen::Index dimension) {
  std::size_t most_vertices = 0;
  for (const PlaneContact& contact : contacts) {
    most_vertices = std::max(most_vertices, contact.surface.vertices.size());
  }
  touching.reserve(most_vertices);
  now.resize(contacts.size());
  unknowns.resize(6 * contacts.size());
  wrenches.resize(6 * contacts.size());
  const auto rows = static_cast<Eigen::Index>(6 * contacts.size());
  matrix.resize(rows, rows);
  rhs.resize(rows);
  x.resize(rows);
  solve_scratch = ConstraintSolveScratch(rows);
  impact_y.resize(dimension);
  onset_y.resize(dimension);
  onset_dydt.resize(dimension);
}

}  // namespace tumble
