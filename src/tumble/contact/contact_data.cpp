#include "tumble/contact/contact_data.hpp"

#include <algorithm>

namespace tumble {

ContactData::ContactData(std::span<const PlaneContact> contacts, std::size_t bodies,
                         Eigen::Index dimension)
    : group_parent(bodies), group_island(bodies), tied_group(bodies, 0), screen(contacts) {
  std::size_t most_vertices = 0;
  for (const PlaneContact& contact : contacts) {
    most_vertices = std::max(most_vertices, contact.surface.vertices.size());
  }
  touching.reserve(most_vertices);
  reserve_feature(landing.feature, most_vertices);
  now.resize(contacts.size());
  // kMostRowsPerContact per contact, and a pair's three. A group's pairs cannot all touch at once:
  // room for kPairsPerBody of them per body of the group (twice the six neighbours a ball has in a
  // random close packing), and more only where more touch.
  constexpr std::size_t kPairRows = 3;
  constexpr std::size_t kPairsPerBody = 6;
  const std::size_t screened = static_cast<std::size_t>(
      std::count_if(contacts.begin(), contacts.end(),
                    [](const PlaneContact& contact) { return contact.screened; }));
  const std::size_t pairs = std::min(screened, kPairsPerBody * screen.bodies().size());
  reserve_rows(kMostRowsPerContact * (contacts.size() - screened) + kPairRows * pairs);
  impact_y.resize(dimension);
  held_in_impact.assign(contacts.size(), 0);
  slipping_after_jump.assign(contacts.size(), 0);
  onset_y.resize(dimension);
  onset_dydt.resize(dimension);
  boxes.resize(screen.bodies().size());
}

void ContactData::reserve_rows(std::size_t count) {
  unknowns.resize(count);
  // Two bodies' per unknown (a pair's impulses), and two per contact (its forces).
  wrenches.resize(2 * count + 2 * now.size());
  const auto rows = static_cast<Eigen::Index>(count);
  matrix.resize(rows, rows);
  rhs.resize(rows);
  x.resize(rows);
  solve_scratch = ConstraintSolveScratch(rows);
  row_scales.resize(rows);
  saved_matrix.resize(rows, rows);
  saved_rhs.resize(rows);
  island_rows.resize(count);
  island_ends.resize(count + 1);
  island_x.resize(rows);
}

}  // namespace tumble
