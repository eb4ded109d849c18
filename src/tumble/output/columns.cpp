#include "tumble/output/columns.hpp"

namespace tumble {

std::vector<std::string> column_names(const ColumnLayout& layout) {
  std::vector<std::string> names;
  for_each_column(layout, [&](std::string_view owner, std::string_view field, auto&&) {
    names.push_back(owner.empty() ? std::string(field)
                                  : std::string(owner) + "." + std::string(field));
  });
  return names;
}

}  // namespace tumble
