#pragma once
// The outcomes of one run (outcome.hpp), accumulated as the run goes, from its rows (final()),
// its continuous solution piece by piece (max, min, mean, conditions: run_reduction.hpp), the
// states just after its events (after()) and its events and jumps: no row is kept.
// A recorder is made once for a scenario's columns and parameters, its expressions compiled
// then, and reused for each run of a sweep on its thread.
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tumble/output/columns.hpp"
#include "tumble/output/row_variables.hpp"
#include "tumble/scenario/expression.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/piece_rows.hpp"
#include "tumble/sweep/outcome.hpp"
#include "tumble/sweep/run_reduction.hpp"

namespace tumble {

class RunRecorder {
 public:
  // Throws std::invalid_argument, naming the outcome, for an expression that does not compile
  // (a name that is neither a column nor a parameter) or an event the scenario cannot have.
  RunRecorder(std::span<const Outcome> outcomes, const ColumnLayout& layout,
              const Scenario& scenario);
  ~RunRecorder();

  // Whether runs of this scenario have the columns and parameters the recorder was made for.
  bool fits(const ColumnLayout& layout, const Scenario& scenario) const;
  // A new run of it: its parameter values, and nothing accumulated.
  void start(const Scenario& scenario);
  // Whether an outcome reads the rows (final() of a column): all others read the pieces, the
  // event states or the events, so a run for them alone need not make a row per output_every.
  bool reads_rows() const { return reads_rows_; }
  void observe(const OutputRow& row);
  // Whether an outcome reads the run between its rows (all but final() of a column): then each
  // run's pieces (PreparedSimulation::on_piece) go to observe_piece.
  bool reads_pieces() const { return reads_pieces_; }
  void observe_piece(PieceRows& piece);
  // Whether an outcome reads the state just after an event (after(EVENT, X)): then each run's
  // rows of those states (PreparedSimulation::on_event_state) go to observe_event_state.
  bool reads_event_states() const { return !after_events_.empty(); }
  void observe_event_state(const OutputRow& row);
  // Each outcome's value, after the last row, with the run's events and, where an outcome reads
  // them, the modes of its initial state (nan without).
  std::vector<double> finish(std::span<const ContactEventRecord> events,
                             std::span<const JumpRecord> jumps,
                             std::span<const UserEventRecord> user_events,
                             const ModesOutcome* modes = nullptr) const;

 private:
  struct AfterEvent;
  // What jump(JUMP, FIELD) reads of the jump: its kinetic energy before or after, or a component
  // of a joint's reaction impulse.
  struct JumpField {
    enum class What { KineticEnergyBefore, KineticEnergyAfter, ReactionImpulse } what{};
    std::size_t joint = 0;  // ReactionImpulse: the joint (Model::joints order)
    int component = 0;      // ReactionImpulse: 0..2 the force's x y z, 3..5 the moment's
  };
  static JumpField jump_field(const std::string& field, std::span<const std::string> joints);
  ColumnLayout layout_;
  RowVariables row_;  // the columns the reductions read, and the run's parameters
  std::vector<std::unique_ptr<RunReduction>> reductions_;
  bool reads_rows_ = false, reads_pieces_ = false;
  // The time of the run's row that row_ holds, if it holds one: at a step's end that row is the
  // piece's sample there, which observe_piece then takes without computing it again.
  std::optional<double> run_row_t_;
  PieceSamples::Need piece_samples_ = PieceSamples::Need::Ends;
  std::vector<std::unique_ptr<AfterEvent>> after_events_;
  // Per outcome: its expression over its reductions' values, and where each value comes from
  // (an index into row_reductions_, or an event reduction).
  struct OutcomeSlots {
    std::unique_ptr<BoundExpression> expression;
    std::unique_ptr<std::vector<double>> values;  // what the expression reads, __r0, __r1, ...
    std::vector<Reduction> reductions;
    std::vector<std::size_t> row_reduction;  // into reductions_ (after(): after_events_)
    std::vector<JumpField> jump_field;       // for jump(): what it reads of the jump
  };
  std::vector<OutcomeSlots> outcomes_;
};

}  // namespace tumble
