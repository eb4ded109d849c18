#include "tumble/scenario/readers.hpp"

namespace tumble::scenario_reading {

std::string BodyGroups::root(const std::string& body) {
  std::string name = body;
  for (auto it = parent_.find(name); it != parent_.end() && it->second != name;
       it = parent_.find(name)) {
    const auto up = parent_.find(it->second);
    if (up != parent_.end()) it->second = up->second;  // halve the path
    name = it->second;
  }
  return name;
}

bool BodyGroups::join(const std::string& a, const std::string& b) {
  const std::string root_a = root(a), root_b = root(b);
  if (root_a == root_b) return false;
  parent_[root_a] = root_b;
  parent_[root_b] = root_b;
  return true;
}

}  // namespace tumble::scenario_reading
