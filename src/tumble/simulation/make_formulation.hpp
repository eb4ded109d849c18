#pragma once
// The formulation a scenario's `simulate.formulation` names, for a model. It sits above
// dynamics/ (the free-body formulations) and multibody/ (joints and contacts), since it chooses
// between them.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tumble/dynamics/formulation.hpp"

namespace tumble {

struct ArticulatedModel;  // multibody/articulated_model.hpp

// Which formulation, over which constant model: what every run of a problem shares (on any
// thread), and what makes each run's formulation. It holds no run object: nothing it reaches is
// written by an evaluation. What callers read of a formulation without running it (its name, its
// elements, its state's size) is computed once, here.
class FormulationModel {
 public:
  // "body" or "textbook"; throws std::invalid_argument otherwise. "body" runs free bodies under
  // gravity alone in the body-frame form, and anything with joints, force elements or loads
  // (whose work the rows report) in the articulated form (joint coordinates), whose tree is
  // built here (std::invalid_argument for joints that close a loop, ...). With
  // `jacobian_wanted` (an implicit method's runs), free bodies too take the articulated form,
  // whose Jacobian the modal equations give (gives_jacobian).
  FormulationModel(std::string_view name, std::shared_ptr<const Model> model,
                   bool jacobian_wanted = false);

  // One run's formulation: the model shared, its own scratch and hybrid state. Safe to call from
  // any thread.
  std::unique_ptr<Formulation> new_run() const;

  const Model& model() const { return *model_; }
  const std::shared_ptr<const Model>& shared_model() const { return model_; }
  // Formulation::name, element_names, keeps_work_ledger and dimension of its runs, and whether
  // their state holds unit quaternions (which rkmk4 moves on the rotation group).
  const std::string& name() const { return name_; }
  const std::vector<std::string>& element_names() const { return element_names_; }
  bool keeps_work_ledger() const { return keeps_work_ledger_; }
  Eigen::Index dimension() const { return dimension_; }
  bool has_unit_quaternions() const { return has_unit_quaternions_; }
  // Whether its runs give their Jacobian df/dy in every mode (an implicit method's need): the
  // articulated form's, its contacts held as their modes hold them (modes/state_jacobian.hpp).
  bool gives_jacobian() const;

 private:
  enum class Kind { BodyFrame, Textbook, Articulated };
  Kind kind_;
  std::shared_ptr<const Model> model_;
  std::shared_ptr<const ArticulatedModel> articulated_;  // Kind::Articulated's tree and layout
  std::string name_;
  std::vector<std::string> element_names_;
  bool keeps_work_ledger_ = false;
  Eigen::Index dimension_ = 0;
  bool has_unit_quaternions_ = false;
};

// One formulation of a model that runs once (FormulationModel(name, model).new_run()).
std::unique_ptr<Formulation> make_formulation(std::string_view name,
                                              std::shared_ptr<const Model> model);
std::unique_ptr<Formulation> make_formulation(std::string_view name, Model model);

}  // namespace tumble
