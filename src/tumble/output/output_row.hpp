#pragma once
// One output row as every sink sees it, and the interface of the sinks: the trajectory CSV, the
// animation page's recording, and whatever comes next (a sweep's reductions, numpy arrays). A run
// hands each row to one RowSink; RowFanOut hands it on to several.
#include <span>
#include <vector>

#include "tumble/body/rigid_body.hpp"
#include "tumble/dynamics/row_extras.hpp"

namespace tumble {

struct OutputRow {
  double t = 0.0;                      // s
  std::span<const BodyState> states;   // one per body, the scenario's order
  const SystemQuantities* quantities;  // KE, PE (gravity and springs), E, p, L about the origin
  const RowExtras* extras;             // joint reactions, contacts, element powers and works
};

class RowSink {
 public:
  virtual ~RowSink() = default;
  // Called with each row in time order; the row's spans are only valid during the call.
  virtual void write_row(const OutputRow& row) = 0;
};

// Hands each row to every sink, in order.
class RowFanOut final : public RowSink {
 public:
  explicit RowFanOut(std::vector<RowSink*> sinks) : sinks_(std::move(sinks)) {}
  void write_row(const OutputRow& row) override {
    for (RowSink* sink : sinks_) sink->write_row(row);
  }

 private:
  std::vector<RowSink*> sinks_;
};

}  // namespace tumble
