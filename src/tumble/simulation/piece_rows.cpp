#include "tumble/simulation/piece_rows.hpp"

#include "tumble/simulation/planar_angles.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {

StateRows::StateRows(const Formulation& formulation, bool planar)
    : formulation_(formulation), planar_(planar), states_(formulation.body_count()) {}

OutputRow StateRows::row_of(double t, const VecX& y, bool with_extras, bool with_quantities) {
  formulation_.unpack_all(y, states_);
  if (with_extras) formulation_.calc_row_extras(t, y, extras_);
  if (planar_) continue_planar_angles(t, states_, extras_);
  if (with_quantities) quantities_ = row_quantities(formulation_.model(), states_, extras_);
  return {t, states_, &quantities_, &extras_};
}

void PieceRows::set_piece(const SolutionPiece& piece, const RowExtras& run_extras) {
  piece_ = &piece;
  if (!started_) {
    // Sized here, once a run: the samples after it reuse these buffers.
    rows_.continue_from(run_extras);
    started_ = true;
  }
}

OutputRow PieceRows::row_at(double t, bool with_extras, bool with_quantities) {
  piece_->state_at(t, y_);
  return rows_.row_of(t, y_, with_extras, with_quantities);
}

}  // namespace tumble
