#include "tumble/output/row_variables.hpp"

#include <algorithm>

namespace tumble {

RowVariables::RowVariables(const ColumnLayout& layout,
                           const std::map<std::string, double>& parameters)
    : layout_(layout), names_(column_names(layout)), column_count_(names_.size()) {
  for (const auto& [name, value] : parameters) {
    names_.push_back(name);
    parameter_names_.push_back(name);
  }
  values_.assign(names_.size(), 0.0);
  for (std::size_t i = 0; i < names_.size(); ++i) variables_.push_back({names_[i], &values_[i]});
  set_parameters(parameters);
}

void RowVariables::set_parameters(const std::map<std::string, double>& parameters) {
  std::size_t i = column_count_;
  for (const auto& [name, value] : parameters) values_[i++] = value;
}

void RowVariables::read_by(std::span<const BoundExpression* const> expressions) {
  std::vector<std::string> read;
  for (const BoundExpression* expression : expressions) {
    read.insert(read.end(), expression->used_names().begin(), expression->used_names().end());
  }
  const auto is_read = [&](const std::string& name) {
    return std::find(read.begin(), read.end(), name) != read.end();
  };
  const auto owns = [](const std::vector<std::string>& owners, std::string_view owner) {
    return std::find(owners.begin(), owners.end(), owner) != owners.end();
  };
  read_.clear();
  reads_extras_ = false;
  reads_quantities_ = false;
  std::size_t i = 0;
  for_each_column(layout_, [&](std::string_view owner, std::string_view field, auto&& value_of) {
    if (is_read(names_[i])) {
      read_.push_back({i, value_of});
      // The joints', contacts' and elements' columns come from the row's extras, and so does
      // the springs' energy in PE and E. (A body named as a joint is counted too: no harm.)
      if (owns(layout_.joints, owner) || owns(layout_.contacts, owner) ||
          owns(layout_.elements, owner) || (owner.empty() && (field == "PE" || field == "E"))) {
        reads_extras_ = true;
      }
      if (owner.empty() && field != "t") reads_quantities_ = true;
    }
    ++i;
  });
}

}  // namespace tumble
