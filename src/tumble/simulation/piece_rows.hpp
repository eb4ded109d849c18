#pragma once
// Output rows of states that are not the trajectory's rows, made as those are: the state just
// after an event (a sweep's after()), and any time of a smooth piece of the run (SolutionPiece)
// from the integrator's continuous extension: what a sweep's reductions read between the rows, a
// maximum where it is, not where a row happened to fall.
#include <span>
#include <vector>

#include "tumble/body/rigid_body.hpp"
#include "tumble/dynamics/formulation.hpp"
#include "tumble/integrators/driver.hpp"
#include "tumble/output/output_row.hpp"

namespace tumble {

// The row of any state of a run, into buffers of its own.
class StateRows {
 public:
  StateRows(const Formulation& formulation, bool planar);

  // From now on, plane angles are counted on from those of `row_extras` (a row's), and the
  // extras not computed keep its values.
  void continue_from(const RowExtras& row_extras) { extras_ = row_extras; }

  // The row of y at t: the bodies' states always; the joints', contacts' and elements' columns
  // (extras) and the system's energies and momenta (quantities) only where asked, as they cost a
  // solve. Valid until the next call.
  OutputRow row_of(double t, const VecX& y, bool with_extras, bool with_quantities);
  // Whether its rows count plane angles on from the last row it made.
  bool planar() const { return planar_; }

 private:
  const Formulation& formulation_;
  bool planar_;
  std::vector<BodyState> states_;
  RowExtras extras_;
  SystemQuantities quantities_;
};

class PieceRows {
 public:
  PieceRows(const Formulation& formulation, bool planar) : rows_(formulation, planar) {}

  // The run's first piece takes its plane angles on from `run_extras` (the first row's, or the
  // last row's before a checkpoint); later ones from the samples before them.
  void set_piece(const SolutionPiece& piece, const RowExtras& run_extras);

  double t_begin() const { return piece_->t_begin(); }
  double t_end() const { return piece_->t_end(); }
  // Whether the piece starts where the last one ended, with nothing between (SolutionPiece).
  bool continues() const { return piece_->continues(); }
  bool is_step_end(double t) const { return piece_->is_step_end(t); }
  // Whether its rows count plane angles on from the last row made here: then no row may be
  // skipped (taken from the run's rows instead), or the next would count on from an older one.
  bool planar() const { return rows_.planar(); }

  // The row at t in [t_begin, t_end] (StateRows::row_of). Valid until the next call.
  OutputRow row_at(double t, bool with_extras, bool with_quantities);

 private:
  StateRows rows_;
  const SolutionPiece* piece_ = nullptr;
  bool started_ = false;
  VecX y_;
};

}  // namespace tumble
