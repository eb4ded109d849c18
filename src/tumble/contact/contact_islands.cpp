// The contact solve island by island (docs/design.md, "Contact islands"). A row's response to an
// unknown is zero unless a body of the row moves with a body the unknown pushes: the rows split
// into islands, the sets of rows that bodies moving together, and contacts between them, tie to
// each other. An obstacle welded to ground ties nothing: it responds to no wrench, so two balls
// on one floor are two islands. A (block-diagonal) A x = b is then one small solve per island,
// with its matrix built from its own rows alone: a bin of balls, each on the floor or in a small
// cluster, costs the sum of its clusters' cubes, not the cube of every row.
//
// Each island is solved as the whole system was (solve_contact_system): its rows in their order
// in the system, the same zero (the largest of every watched contact's), and where they are
// redundant the least weighted norm, which for a block-diagonal system is each block's. With
// one island the solve is the whole system's, operation for operation.
#include <algorithm>
#include <span>
#include <vector>

#include "tumble/contact/contact_system.hpp"

namespace tumble {

namespace {

constexpr std::size_t kNoIsland = static_cast<std::size_t>(-1);

}  // namespace

double ContactSystem::rows_zero(RowQuantity rows) const {
  double zero = 0.0;
  for (const std::size_t c : watched()) {
    const ContactStatus& s = s_.contacts[c];
    // Not a group's pairs apart: which of them the broad phase watches must not change a solve.
    if (contacts_[c].screened && s.mode == ContactMode::Apart) continue;
    zero = std::max(zero, rows == RowQuantity::Position   ? s.touching_height
                          : rows == RowQuantity::Velocity ? s.slip_zero
                                                          : s.slip_zero / s.time_scale);
  }
  return zero;
}

Eigen::Index ContactSystem::find_islands(Eigen::Index count) const {
  std::vector<std::size_t>& parent = d_.group_parent;
  std::vector<std::size_t>& island = d_.group_island;
  const auto root = [&](std::size_t group) {
    while (parent[group] != group) {
      parent[group] = parent[parent[group]];
      group = parent[group];
    }
    return group;
  };
  const auto row_at = [&](Eigen::Index i) -> const ContactUnknown& {
    return d_.unknowns[static_cast<std::size_t>(i)];
  };
  // The group a row's island is found by: its body's, or where that cannot move, the other
  // body's (a ball on a welded obstacle: the ball's).
  const auto row_group = [&](const ContactUnknown& row) {
    const PlaneContact& contact = contacts_[row.contact];
    if (!dynamics_.can_move(contact.body) && contact.touches_a_body() &&
        dynamics_.can_move(contact.other_body)) {
      return dynamics_.motion_group(contact.other_body);
    }
    return dynamics_.motion_group(contact.body);
  };
  for (Eigen::Index i = 0; i < count; ++i) {
    const PlaneContact& contact = contacts_[row_at(i).contact];
    for (const std::size_t body : {contact.body, contact.other_body}) {
      if (body == contact.other_body && !contact.touches_a_body()) continue;
      const std::size_t group = dynamics_.motion_group(body);
      parent[group] = group;
      island[group] = kNoIsland;
    }
  }
  // A contact between two bodies that both move ties their groups; the smaller root stays.
  for (Eigen::Index i = 0; i < count; ++i) {
    const PlaneContact& contact = contacts_[row_at(i).contact];
    if (!contact.touches_a_body() || !dynamics_.can_move(contact.body) ||
        !dynamics_.can_move(contact.other_body)) {
      continue;
    }
    const std::size_t a = root(dynamics_.motion_group(contact.body));
    const std::size_t b = root(dynamics_.motion_group(contact.other_body));
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
  // The islands in the order of their first rows, each one's rows in the system's order
  // (a counting sort: island_ends first counts, then marks each island's end).
  Eigen::Index islands = 0;
  std::vector<Eigen::Index>& ends = d_.island_ends;
  for (Eigen::Index i = 0; i < count; ++i) {
    const std::size_t r = root(row_group(row_at(i)));
    if (island[r] == kNoIsland) {
      island[r] = static_cast<std::size_t>(islands);
      ends[static_cast<std::size_t>(++islands)] = 0;
    }
    ++ends[island[r] + 1];
  }
  ends[0] = 0;
  for (Eigen::Index k = 0; k < islands; ++k) {
    ends[static_cast<std::size_t>(k) + 1] += ends[static_cast<std::size_t>(k)];
  }
  for (Eigen::Index i = 0; i < count; ++i) {
    const std::size_t k = island[root(row_group(row_at(i)))];
    d_.island_rows[static_cast<std::size_t>(ends[k]++)] = i;
  }
  return islands;  // island k ends at ends[k] and starts at ends[k - 1] (0 for the first)
}

void ContactSystem::solve_contact_rows(Eigen::Index count, VecX& x, RowQuantity quantity) const {
  if (count == 0) return;
  const double zero = rows_zero(quantity);
  const Eigen::Index islands = find_islands(count);
  Eigen::Index start = 0;
  for (Eigen::Index k = 0; k < islands; ++k) {
    const Eigen::Index end = d_.island_ends[static_cast<std::size_t>(k)];
    const std::span<const Eigen::Index> rows(d_.island_rows.data() + start,
                                             static_cast<std::size_t>(end - start));
    for (std::size_t i = 0; i < rows.size(); ++i) {
      d_.island_x(static_cast<Eigen::Index>(i)) = x(rows[i]);
    }
    calc_contact_matrix(rows);
    solve_contact_system(rows, d_.island_x, zero);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      x(rows[i]) = d_.island_x(static_cast<Eigen::Index>(i));
    }
    start = end;
  }
}

}  // namespace tumble
