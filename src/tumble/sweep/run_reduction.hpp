#pragma once
// One reduction of a run over its columns (final, max, min, mean, time_of_max, and first and
// count of a condition), gathered as the run goes. All but final() read the run's continuous
// solution, piece by piece (PieceRows), not its rows: each piece is sampled at its ends (and its
// middle for a maximum), a maximum beside the highest sample is found on the continuous extension
// by Brent's method, and a condition's turn between two samples located there to a few ulps of t. A
// mean takes two more samples, at Gauss-Lobatto's points, and integrates by their five-point rule
// (exact for a polynomial of degree 7). Their values do not depend on output_every.
#include <array>
#include <memory>
#include <span>
#include <string>

#include "tumble/math/function_ref.hpp"
#include "tumble/scenario/expression.hpp"
#include "tumble/sweep/outcome.hpp"

namespace tumble {

// A piece's samples: at t[0] = its start ... t[count - 1] = its end, what the run's reductions
// read: the ends alone where only conditions are read (a step's end is the integrator's own state,
// so no continuous extension is evaluated unless a condition turns inside), its middle too for a
// maximum or minimum (three), or for a mean Gauss-Lobatto's five points. A piece of no width (the
// state just after a jump, at its instant) has one.
struct PieceSamples {
  static constexpr int kNodes = 5;
  // What the reductions need of each piece, fewest samples first.
  enum class Need { Ends, Middle, Mean };
  std::array<double, kNodes> t{};
  int count = kNodes;
  // Whether t[0] was sampled for this piece (the run's start, or just after a jump or a change
  // of modes); otherwise t[0] is the last piece's end, which each reduction already has.
  bool fresh_start = true;
  // The samples on [a, b], the ends exactly.
  static PieceSamples on(double a, double b, bool fresh_start, Need need);
};

class RunReduction {
 public:
  // Throws ExpressionError for text that does not compile against `variables`.
  RunReduction(ReductionKind kind, const std::string& text,
               std::span<const BoundExpression::Variable> variables);

  // What it evaluates: its expression, and for a condition that is one comparison A < B, A - B.
  const BoundExpression& value() const { return value_; }
  const BoundExpression* margin() const { return margin_.get(); }
  ReductionKind kind() const { return kind_; }
  bool reads_pieces() const { return kind_ != ReductionKind::Final; }

  void start();  // a new run
  // final(): each row, its variables loaded.
  void observe_row();
  // The value (and margin) at sample k of a piece, its variables loaded; then, after the last
  // sample, the piece itself, with `load(t)` loading the variables at any t in it (to refine a
  // maximum or locate a turn).
  void take_sample(int k);
  void observe_piece(const PieceSamples& samples, FunctionRef<void(double t)> load);
  double result() const;

 private:
  void observe_extremum(const PieceSamples& samples, FunctionRef<void(double t)> load);
  void observe_mean(const PieceSamples& samples);
  void observe_turns(const PieceSamples& samples, FunctionRef<void(double t)> load);
  // Keeps (t, value) where it beats the best so far (max: above; min: below), or is the first.
  void consider(double t, double value);

  ReductionKind kind_;
  BoundExpression value_;
  std::unique_ptr<BoundExpression> margin_;
  std::array<double, PieceSamples::kNodes> values_{}, margins_{};  // this piece's samples
  bool sampled_ = false;  // whether the run has had a sample (or, for final, a row)
  double last_ = 0.0;     // the value at the last sample (final: row)
  double last_margin_ = 0.0;
  bool has_best_ = false;
  double best_ = 0.0, t_best_ = 0.0;       // max, min, time_of_max
  double integral_ = 0.0, covered_ = 0.0;  // mean: of the value, and of time
  double turns_ = 0.0, turned_at_ = 0.0;   // first, count
};

}  // namespace tumble
