#pragma once
// The formulation a scenario's `simulate.formulation` names, for a model. It sits above
// dynamics/ (the free-body formulations) and multibody/ (joints and contacts), since it chooses
// between them.
#include <memory>
#include <string_view>

#include "tumble/dynamics/formulation.hpp"

namespace tumble {

// "body" or "textbook"; throws std::invalid_argument otherwise. "body" runs free bodies under
// gravity alone in the body-frame form, and anything with joints, force elements or loads (whose
// work the rows report) in the articulated form (joint coordinates). The model is shared, not
// copied: formulation->new_run() gives more runs of it.
std::unique_ptr<Formulation> make_formulation(std::string_view name,
                                              std::shared_ptr<const Model> model);
std::unique_ptr<Formulation> make_formulation(std::string_view name, Model model);

}  // namespace tumble
