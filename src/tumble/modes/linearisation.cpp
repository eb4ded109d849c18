#include "tumble/modes/linearisation.hpp"

#include <fmt/core.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

#include "tumble/contact/plane_contact.hpp"
#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

namespace {

// A position block: the coordinates of one joint's place (a free body has two: where its COM is,
// and how it is turned).
struct PositionBlock {
  Eigen::Index first = 0, count = 0;
};

std::vector<PositionBlock> position_blocks(const ArticulatedModel& model,
                                           const ModalLayout& layout) {
  std::vector<PositionBlock> blocks;
  for (std::size_t k = 0; k < model.tree.size(); ++k) {
    const Eigen::Index o = layout.position_offset[k];
    if (o < 0 || model.tree[k].nv == 0) continue;
    Eigen::Index first = o;
    for (const int count : model.tree[k].kind->modal_position_blocks()) {
      blocks.push_back({first, count});
      first += count;
    }
  }
  return blocks;
}

// Whether moving a block that nothing depends on (to first order) by finite amounts leaves the
// rates and their Jacobian (the rows still kept, other than its own) as they are: a symmetry of
// the model, such as a wheel's angle on its axle where the wheel is round about it, rather than a
// coordinate whose restoring terms vanish only to first order (a mast exactly at its critical
// spring). Two amounts, neither a simple fraction of a turn, so that a shape with a few-fold
// symmetry (a square wheel) is not taken for a round one.
bool finite_moves_change_nothing(const ModalEquations& equations, const PositionBlock& block,
                                 const std::vector<bool>& kept_row, const VecX& f0, const MatX& J,
                                 double rate_tolerance, double tolerance) {
  const Eigen::Index n = equations.layout().size();
  for (const double amount : {0.7, -2.3}) {
    VecX moved;
    const MatX J_moved = jacobian_at_zero(
        [&](const VecXOf<Dual>& z) {
          VecXOf<Dual> at = z;
          for (Eigen::Index i = block.first; i < block.first + block.count; ++i) at(i) += amount;
          return equations.rates<Dual>(at);
        },
        n, &moved);
    for (Eigen::Index i = 0; i < n; ++i) {
      if (!kept_row[static_cast<std::size_t>(i)]) continue;
      if (i >= block.first && i < block.first + block.count) continue;
      if (std::abs(moved(i) - f0(i)) > rate_tolerance) return false;
      if ((J_moved.row(i) - J.row(i)).cwiseAbs().maxCoeff() > tolerance) return false;
    }
  }
  return true;
}

// The candidates for a steady motion's turns: each body on a ball or free joint with an axis of
// symmetry spinning about it (a sphere or a cube about the axis it spins about), then the whole
// turning about the vertical.
std::vector<Symmetry> candidate_symmetries(const ModalEquations& equations) {
  const ArticulatedModel& m = equations.model();
  std::vector<Symmetry> spins;
  for (std::size_t k = 0; k < m.tree.size(); ++k) {
    const TreeJoint& joint = m.tree[k];
    if (equations.layout().position_offset[k] < 0) continue;
    if (!joint.kind->turns_freely()) continue;
    const RigidBody& body = m.model.bodies[joint.child];
    const Eigen::SelfAdjointEigenSolver<Mat3> principal(body.I_G_B);
    const Vec3& I = principal.eigenvalues();  // ascending
    const double close = 1e-9 * I(2);
    Vec3 axis;
    if (I(2) - I(0) <= close) {
      const Vec3 omega_C = equations.y0().segment<3>(joint.v);
      if (omega_C.norm() == 0.0) continue;
      axis = omega_C.normalized();
    } else if (I(1) - I(0) <= close) {
      axis = principal.eigenvectors().col(2);
    } else if (I(2) - I(1) <= close) {
      axis = principal.eigenvectors().col(0);
    } else {
      continue;
    }
    spins.push_back({Symmetry::Kind::BodySpin, axis, k,
                     fmt::format("{} spinning about its axis of symmetry", body.name)});
  }
  const double g = m.model.gravity_W.norm();
  if (g > 0.0) {
    spins.push_back({Symmetry::Kind::WorldTurn, -m.model.gravity_W / g, 0,
                     "the whole turning about the vertical"});
  }
  return spins;
}

MatX rows_and_columns(const MatX& J, const std::vector<Eigen::Index>& kept) {
  const auto n = static_cast<Eigen::Index>(kept.size());
  MatX out(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) out(i, j) = J(kept[i], kept[j]);
  }
  return out;
}

VecX rows(const VecX& v, const std::vector<Eigen::Index>& kept) {
  VecX out(static_cast<Eigen::Index>(kept.size()));
  for (std::size_t i = 0; i < kept.size(); ++i) out(static_cast<Eigen::Index>(i)) = v(kept[i]);
  return out;
}

// An orthonormal basis of the range of M (columns), its rank taken at `relative` of its
// largest singular value.
MatX orthonormal_range(const MatX& M, double relative) {
  if (M.cols() == 0) return MatX(M.rows(), 0);
  const Eigen::JacobiSVD<MatX> svd(M, Eigen::ComputeThinU);
  const VecX& sigma = svd.singularValues();
  Eigen::Index rank = 0;
  while (rank < sigma.size() && sigma(rank) > relative * std::max(sigma(0), 1e-300)) ++rank;
  return svd.matrixU().leftCols(rank);
}

// Whether x lies in the span of the orthonormal columns of T (to round-off).
bool in_span(const MatX& T, const VecX& x) {
  return (x - T * (T.transpose() * x)).norm() <= 1e-9 * std::max(x.norm(), 1e-300);
}

// The touching contacts must hold with what the plane (or the other body) can give: their points
// not slipping (or, frictionless, not leaving it), pressed on (N > 0), inside the friction cone.
void check_contacts(const ModalEquations& equations, double speed_scale) {
  const Model& model = equations.model().model;
  const VecX values = equations.constraints<double>(VecX::Zero(equations.layout().size()));
  const std::vector<Vec3> forces = equations.contact_forces();
  Eigen::Index row = 0;
  for (std::size_t i = 0; i < equations.contacts().size(); ++i) {
    const ModalContact& held = equations.contacts()[i];
    const PlaneContact& contact = model.contacts[held.contact];
    ++row;  // the height (a pair's gap), at the plane by touching_contacts
    const double slip = values.segment(row, held.rows()).norm();
    row += held.rows();
    if (slip > 1e-9 * speed_scale * std::max(1.0, contact_size(contact.surface))) {
      throw NotSteady(
          held.rolls ? fmt::format("contact {}: its point slides at {:.6g} m/s; a sliding contact "
                                   "(Coulomb's friction against the slip) is not linearised, only "
                                   "rolling, sticking and frictionless ones",
                                   contact.name, slip)
                     : fmt::format("contact {}: its point moves off the {} at {:.6g} m/s",
                                   contact.name, held.pair ? "other body" : "plane", slip));
    }
    const double N = forces[i].dot(held.normal_W);
    // Touching with no force between (balls hanging side by side): the least motion parts them
    // or presses them together, and the motion has no linearisation there.
    const double weight = model.bodies[contact.body].mass * model.gravity_W.norm();
    if (std::abs(N) <= 1e-9 * weight) {
      throw NotSteady(fmt::format(
          "contact {}: {} without pressing (N = {:.3g} N): the least motion parts them or presses "
          "them together, and has no linearisation there; start them apart, or pressed",
          contact.name, held.pair ? "the two bodies touch" : "the body touches the plane", N));
    }
    if (N <= 0.0) {
      throw NotSteady(
          held.pair ? fmt::format("contact {}: the two bodies would have to pull on each other "
                                  "(N = {:.6g} N): they come apart",
                                  contact.name, N)
                    : fmt::format("contact {}: the plane would have to pull (N = {:.6g} N): the "
                                  "body lifts off",
                                  contact.name, N));
    }
    const double friction = (forces[i] - N * held.normal_W).norm();
    if (friction > contact.friction * N * (1.0 + 1e-9)) {
      throw NotSteady(fmt::format(
          "contact {}: holding its point needs a friction force of {:.6g} N, more than mu N = "
          "{:.6g} N: it slides",
          contact.name, friction, contact.friction * N));
    }
  }
}

// An orthonormal basis T (columns, over the kept coordinates) of the contacts' and the loops'
// tangent space: the changes the linearised constraints allow (C dz = 0), with the positions set
// aside free to take up what they can (a rolling disk's height follows its lean).
MatX constraint_tangent(const MatX& C, const std::vector<Eigen::Index>& kept) {
  const Eigen::Index n = C.cols();
  const Eigen::JacobiSVD<MatX> svd(C, Eigen::ComputeFullV);
  const VecX& sigma = svd.singularValues();
  Eigen::Index rank = 0;
  while (rank < sigma.size() && sigma(rank) > 1e-10 * std::max(sigma(0), 1.0)) ++rank;
  const MatX allowed = svd.matrixV().rightCols(n - rank);
  // The constraints take every freedom (a mechanism driven at a speed): no change is allowed.
  if (allowed.cols() == 0) return MatX(static_cast<Eigen::Index>(kept.size()), 0);
  MatX allowed_kept(static_cast<Eigen::Index>(kept.size()), allowed.cols());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    allowed_kept.row(static_cast<Eigen::Index>(i)) = allowed.row(kept[i]);
  }
  return orthonormal_range(allowed_kept, 1e-10);
}

}  // namespace

MatX jacobian_at_zero(const std::function<VecXOf<Dual>(const VecXOf<Dual>&)>& f, Eigen::Index n,
                      VecX* value) {
  MatX J;
  VecXOf<Dual> z(n);
  // At least one evaluation, for the value where nothing can move (n = 0).
  for (Eigen::Index first = 0; first == 0 || first < n; first += kDualSeeds) {
    const Eigen::Index seeds = std::min<Eigen::Index>(kDualSeeds, n - first);
    for (Eigen::Index i = 0; i < n; ++i) {
      const bool seeded = i >= first && i < first + seeds;
      z(i) = seeded ? Dual(0.0, DualDerivatives::Unit(seeds, i - first)) : Dual(0.0);
    }
    const VecXOf<Dual> out = f(z);
    if (first == 0) {
      J.setZero(out.size(), n);
      if (value != nullptr) {
        value->resize(out.size());
        for (Eigen::Index i = 0; i < out.size(); ++i) (*value)(i) = out(i).value();
      }
    }
    for (Eigen::Index i = 0; i < out.size(); ++i) {
      // A result that depends on none of these seeds keeps no derivatives.
      if (out(i).derivatives().size() == seeds) {
        J.block(i, first, 1, seeds) = out(i).derivatives().transpose();
      }
    }
  }
  return J;
}

Linearisation linearise(const ModalEquations& equations) {
  const ArticulatedModel& m = equations.model();
  const ModalLayout& layout = equations.layout();
  const Eigen::Index n = layout.size();
  if (n == 0) throw NotSteady("joints: nothing can move (every joint is fixed, locked or driven)");

  VecX f0;
  const MatX J =
      jacobian_at_zero([&](const VecXOf<Dual>& z) { return equations.rates<Dual>(z); }, n, &f0);
  Linearisation result;
  const double scale = 1.0 + J.cwiseAbs().maxCoeff();
  // Round-off in J and in the rates grows with their size; a rate or a dependence below these is
  // taken as zero. Speeds multiply the Jacobian into rates, hence rate_tolerance.
  const double tolerance = 1e-10 * scale;
  // The positions' rates at y0 are the speeds.
  const double speed_scale =
      layout.position_count > 0
          ? std::max(1.0, f0.head(layout.position_count).cwiseAbs().maxCoeff())
          : 1.0;
  const double rate_tolerance = 1e-9 * scale * speed_scale;
  if (!equations.contacts().empty()) check_contacts(equations, speed_scale);

  // The contacts' and the loops' constraints, to first order: C dz = 0.
  const MatX C = equations.holds_constraints()
                     ? jacobian_at_zero(
                           [&](const VecXOf<Dual>& z) { return equations.constraints<Dual>(z); }, n)
                     : MatX(0, n);
  const double constraint_tolerance =
      1e-10 * std::max(1.0, C.size() > 0 ? C.cwiseAbs().maxCoeff() : 0.0);

  // Step 2: ignorable positions.
  std::vector<bool> kept_row(static_cast<std::size_t>(n), true);
  std::vector<PositionBlock> blocks = position_blocks(m, layout);
  for (bool changed = true; changed;) {
    changed = false;
    for (auto block = blocks.begin(); block != blocks.end(); ++block) {
      double dependence = 0.0;
      for (Eigen::Index i = 0; i < n; ++i) {
        if (!kept_row[static_cast<std::size_t>(i)]) continue;
        if (i >= block->first && i < block->first + block->count) continue;
        dependence = std::max(dependence,
                              J.row(i).segment(block->first, block->count).cwiseAbs().maxCoeff());
      }
      if (dependence > tolerance) continue;
      // A free body's place and turn are symmetries; so is a joint's coordinate that moving by
      // finite amounts changes nothing. One that the constraints hold (a bicycle frame's pitch,
      // which its front wheel's contact fixes) cannot drift either. Any other that nothing
      // restores is neutral only to first order.
      const bool held =
          C.rows() > 0 &&
          C.middleCols(block->first, block->count).cwiseAbs().maxCoeff() > constraint_tolerance;
      const bool restored =
          held ||
          m.tree[layout.coordinates[static_cast<std::size_t>(block->first)].tree_joint]
              .kind->modal_positions_are_symmetries() ||
          finite_moves_change_nothing(equations, *block, kept_row, f0, J, rate_tolerance,
                                      tolerance);
      for (Eigen::Index i = block->first; i < block->first + block->count; ++i) {
        kept_row[static_cast<std::size_t>(i)] = false;
        const ModalCoordinate& coordinate = layout.coordinates[static_cast<std::size_t>(i)];
        result.ignorable.push_back(coordinate.name);
        if (std::abs(f0(i)) > rate_tolerance) {
          result.drifting.push_back({coordinate.name, coordinate.unit, f0(i)});
        }
        if (!restored) result.unrestored.push_back(coordinate.name);
      }
      blocks.erase(block);
      changed = true;
      break;
    }
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!kept_row[static_cast<std::size_t>(i)]) continue;
    result.kept.push_back(i);
    result.coordinates.push_back(layout.coordinates[static_cast<std::size_t>(i)]);
  }
  if (result.kept.empty()) {
    throw NotSteady("every coordinate is ignorable: nothing acts that a small change could alter");
  }
  const VecX f_s = rows(f0, result.kept);
  MatX A = rows_and_columns(J, result.kept);
  const auto ns = static_cast<Eigen::Index>(result.kept.size());
  result.tangent = equations.holds_constraints() ? constraint_tangent(C, result.kept)
                                                 : MatX(MatX::Identity(ns, ns));
  if (result.tangent.cols() == 0) {
    throw NotSteady(
        "joints: nothing can move: the loops' and the contacts' constraints take every freedom "
        "the other joints leave (a mechanism driven at a speed moves as the drive says)");
  }

  // Step 3: steady? First as an equilibrium, then with the spins, then with the turn about the
  // vertical as well.
  const std::vector<Symmetry> candidates = candidate_symmetries(equations);
  const auto field_of = [&](const Symmetry& s) {
    VecX X0;
    MatX DX = jacobian_at_zero(
        [&](const VecXOf<Dual>& z) { return equations.symmetry_field<Dual>(s, z); }, n, &X0);
    return std::make_pair(X0, DX);
  };
  std::vector<std::pair<VecX, MatX>> fields;
  for (const Symmetry& s : candidates) fields.push_back(field_of(s));

  VecX residual = f_s;
  std::vector<std::size_t> used;
  VecX c;
  if (f_s.cwiseAbs().maxCoeff() > rate_tolerance) {
    std::vector<std::size_t> spins, all;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (candidates[i].kind == Symmetry::Kind::BodySpin) spins.push_back(i);
      all.push_back(i);
    }
    for (const std::vector<std::size_t>& trial : {spins, all}) {
      if (trial.empty()) continue;
      MatX X(f_s.size(), static_cast<Eigen::Index>(trial.size()));
      for (std::size_t i = 0; i < trial.size(); ++i) {
        X.col(static_cast<Eigen::Index>(i)) = rows(fields[trial[i]].first, result.kept);
      }
      const Eigen::CompleteOrthogonalDecomposition<MatX> fit(X);
      const VecX rates = fit.solve(f_s);
      const VecX left = f_s - X * rates;
      if (left.cwiseAbs().maxCoeff() < residual.cwiseAbs().maxCoeff()) {
        residual = left;
        used = trial;
        c = rates;
      }
      if (left.cwiseAbs().maxCoeff() <= rate_tolerance) break;
    }
  }
  Eigen::Index worst = 0;
  const double off = residual.cwiseAbs().maxCoeff(&worst);
  if (off > rate_tolerance) {
    const ModalCoordinate& coordinate = result.coordinates[static_cast<std::size_t>(worst)];
    std::string what = coordinate.is_speed
                           ? fmt::format("{} changes at {:.6g} {}/s", coordinate.name,
                                         residual(worst), coordinate.unit)
                           : fmt::format("{} moves at {:.6g} {}/s", coordinate.name,
                                         residual(worst), coordinate.unit);
    what = "the initial state is neither an equilibrium nor a steady motion: " + what;
    if (!used.empty()) what += " even as the state turns with its symmetries";
    throw NotSteady(what);
  }
  result.largest_rate = off;

  // The turns that carry the steady motion: each must commute with the motion ([X, f] = 0),
  // or the frame that moves with it would see the equations change.
  std::vector<VecX> orbit;
  result.symmetry_rates.resize(0);
  for (std::size_t i = 0; i < used.size(); ++i) {
    const double rate = c(static_cast<Eigen::Index>(i));
    if (std::abs(rate) * scale <= rate_tolerance) continue;
    const auto& [X0, DX] = fields[used[i]];
    const VecX bracket = rows(J * X0 - DX * f0, result.kept);
    if (bracket.cwiseAbs().maxCoeff() > rate_tolerance * (1.0 + std::abs(rate))) {
      throw NotSteady(fmt::format(
          "the initial state turns as {} at {:.6g} rad/s, but the loads change as it turns: "
          "not a steady motion",
          candidates[used[i]].description, rate));
    }
    const VecX X_s = rows(X0, result.kept);
    if (!in_span(result.tangent, X_s)) {
      throw NotSteady(fmt::format(
          "the initial state turns as {} at {:.6g} rad/s, but the contacts do not allow that "
          "turn: not a steady motion",
          candidates[used[i]].description, rate));
    }
    result.symmetries.push_back(candidates[used[i]]);
    result.symmetry_rates.conservativeResize(result.symmetry_rates.size() + 1);
    result.symmetry_rates(result.symmetry_rates.size() - 1) = rate;
    A -= rate * rows_and_columns(DX, result.kept);
    orbit.push_back(X_s);
  }
  // The turns the state does not move along but that carry its motion over unchanged (a rolling
  // wheel's heading, a hanging body's turn about the vertical): the steady motions they reach
  // are a neutral family, which would show as a drift (a repeated zero) if left in.
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const auto& [X0, DX] = fields[i];
    const VecX X_s = rows(X0, result.kept);
    if (X_s.norm() <= tolerance || !in_span(result.tangent, X_s)) continue;
    if (rows(J * X0 - DX * f0, result.kept).cwiseAbs().maxCoeff() > rate_tolerance) continue;
    MatX spanned(ns, static_cast<Eigen::Index>(orbit.size()));
    for (std::size_t j = 0; j < orbit.size(); ++j) {
      spanned.col(static_cast<Eigen::Index>(j)) = orbit[j];
    }
    if (!orbit.empty() && in_span(orthonormal_range(spanned, 1e-9), X_s)) continue;
    result.neutral_symmetries.push_back(candidates[i]);
    orbit.push_back(X_s);
  }
  result.orbit.resize(ns, static_cast<Eigen::Index>(orbit.size()));
  for (std::size_t j = 0; j < orbit.size(); ++j) {
    result.orbit.col(static_cast<Eigen::Index>(j)) = orbit[j];
  }
  result.A = A;

  // Step 4: the quotient, within the constraints' tangent space T, by the directions along the
  // orbit (with neither, Q is the identity): with O = T^T orbit = [P' Q'] R, P = T P', Q = T Q'.
  const Eigen::Index dimension = result.tangent.cols();
  const MatX along = result.tangent.transpose() * result.orbit;
  const MatX basis =
      Eigen::HouseholderQR<MatX>(along).householderQ() * MatX::Identity(dimension, dimension);
  result.orbit_basis = result.tangent * basis.leftCols(along.cols());
  result.quotient = result.tangent * basis.rightCols(dimension - along.cols());
  return result;
}

}  // namespace tumble
