#pragma once
// Expressions over an output row's columns and the scenario's parameters: a sweep's reductions
// ("min(prism.w3)"), a scenario's events ("box.x > d"). Every column (by its CSV name) and every
// parameter is a variable an expression may name; once the expressions are compiled, each row
// fills in only the columns they read, so a row costs what the expressions need, not the 50-odd
// columns of a body.
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "tumble/output/columns.hpp"
#include "tumble/scenario/expression.hpp"

namespace tumble {

class RowVariables {
 public:
  RowVariables(const ColumnLayout& layout, const std::map<std::string, double>& parameters);
  RowVariables(const RowVariables&) = delete;
  RowVariables& operator=(const RowVariables&) = delete;

  // The columns, then the parameters: what expressions over a row are compiled against. The
  // values they point at stay where they are for the object's life.
  std::span<const BoundExpression::Variable> variables() const { return variables_; }
  std::span<const BoundExpression::Variable> parameter_variables() const {
    return std::span(variables_).subspan(column_count_);
  }
  const std::vector<std::string>& parameter_names() const { return parameter_names_; }

  // From now on take() fills in the columns these expressions read, and only those.
  void read_by(std::span<const BoundExpression* const> expressions);
  // Whether a column read is the joints', contacts' or elements' (RowExtras), or an energy that
  // holds the springs' (PE, E): a row needs its extras computed.
  bool reads_extras() const { return reads_extras_; }
  // Whether a column read is the system's (KE, PE, E, p, L): a row needs its quantities.
  bool reads_quantities() const { return reads_quantities_; }

  // New parameter values (the same names, a sweep's next run).
  void set_parameters(const std::map<std::string, double>& parameters);
  // The columns read, from this row.
  void take(const OutputRow& row) {
    for (const ReadColumn& column : read_) values_[column.index] = column.value_of(row);
  }

 private:
  struct ReadColumn {
    std::size_t index;                                 // in values_
    std::function<double(const OutputRow&)> value_of;  // for_each_column's
  };
  ColumnLayout layout_;
  std::vector<std::string> names_;  // the columns', then the parameters'
  std::vector<std::string> parameter_names_;
  std::size_t column_count_ = 0;
  std::vector<double> values_;  // as names_
  std::vector<BoundExpression::Variable> variables_;
  std::vector<ReadColumn> read_;
  bool reads_extras_ = false;
  bool reads_quantities_ = false;
};

}  // namespace tumble
