#include "tumble/contact/contact_data.hpp"

#include <algorithm>

namespace tumble {

ContactData::ContactData(std::span<const PlaneContact> contacts, Eigen::Index dimension) {
  std::size_t most_vertices = 0;
  for (const PlaneContact& contact : contacts) {
    most_vertices = std::max(most_vertices, contact.surface.vertices.size());
  }
  touching.reserve(most_vertices);
  reserve_feature(landing.feature, most_vertices);
  // Rows per contact at most: a face's six; a held polyhedron's three at each of three points.
  constexpr std::size_t kMostRows = 9;
  now.resize(contacts.size());
  unknowns.resize(kMostRows * contacts.size());
  wrenches.resize(kMostRows * contacts.size());
  const auto rows = static_cast<Eigen::Index>(kMostRows * contacts.size());
  matrix.resize(rows, rows);
  rhs.resize(rows);
  x.resize(rows);
  solve_scratch = ConstraintSolveScratch(rows);
  row_scales.resize(rows);
  saved_matrix.resize(rows, rows);
  saved_rhs.resize(rows);
  impact_y.resize(dimension);
  held_in_impact.assign(contacts.size(), 0);
  onset_y.resize(dimension);
  onset_dydt.resize(dimension);
}

}  // namespace tumble
