#include "tumble/simulation/make_formulation.hpp"

#include <stdexcept>
#include <string>

#include "tumble/dynamics/body_frame_formulation.hpp"
#include "tumble/dynamics/textbook_formulation.hpp"
#include "tumble/modes/state_jacobian.hpp"
#include "tumble/multibody/articulated_formulation.hpp"

namespace tumble {

FormulationModel::FormulationModel(std::string_view name, std::shared_ptr<const Model> model,
                                   bool jacobian_wanted)
    : model_(std::move(model)) {
  const bool gravity_only = model_->bodies_are_free() && model_->loads.empty();
  if (name == "body") {
    kind_ = gravity_only && !jacobian_wanted ? Kind::BodyFrame : Kind::Articulated;
    if (kind_ == Kind::Articulated) articulated_ = std::make_shared<const ArticulatedModel>(model_);
  } else if (name == "textbook") {
    if (!model_->bodies_are_free()) {
      throw std::invalid_argument(
          "formulation textbook integrates free bodies (the chapter's [R; omega]); joints, "
          "springs and impulses need formulation: body");
    }
    kind_ = Kind::Textbook;
  } else {
    throw std::invalid_argument("unknown formulation '" + std::string(name) +
                                "'; valid: body, textbook");
  }
  // Read once from a run that is then dropped, so that they are the formulation's own answers.
  const std::unique_ptr<Formulation> run = new_run();
  name_ = std::string(run->name());
  element_names_ = run->element_names();
  keeps_work_ledger_ = run->keeps_work_ledger();
  dimension_ = run->dimension();
  has_unit_quaternions_ = !run->unit_quaternion_offsets().empty();
}

bool FormulationModel::gives_jacobian() const {
  return kind_ == Kind::Articulated;
}

std::unique_ptr<Formulation> FormulationModel::new_run() const {
  switch (kind_) {
    case Kind::BodyFrame:
      return std::make_unique<BodyFrameFormulation>(model_);
    case Kind::Textbook:
      return std::make_unique<TextbookFormulation>(model_);
    case Kind::Articulated: {
      auto run = std::make_unique<ArticulatedFormulation>(articulated_);
      run->set_state_jacobian(&calc_state_jacobian);
      return run;
    }
  }
  throw std::logic_error("FormulationModel: no such kind");
}

std::unique_ptr<Formulation> make_formulation(std::string_view name,
                                              std::shared_ptr<const Model> model) {
  return FormulationModel(name, std::move(model)).new_run();
}

std::unique_ptr<Formulation> make_formulation(std::string_view name, Model model) {
  return make_formulation(name, std::make_shared<const Model>(std::move(model)));
}

}  // namespace tumble
