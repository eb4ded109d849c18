#pragma once
#include <stdexcept>

namespace tumble {

// The initial state is neither an equilibrium nor a steady motion (or the model is one a
// linearisation does not cover): `tumble modes` exits with status 6 and this message.
class NotSteady : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace tumble
