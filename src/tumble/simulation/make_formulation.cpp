#include "tumble/simulation/make_formulation.hpp"

#include <stdexcept>
#include <string>

#include "tumble/dynamics/body_frame_formulation.hpp"
#include "tumble/dynamics/textbook_formulation.hpp"
#include "tumble/multibody/articulated_formulation.hpp"

namespace tumble {

std::unique_ptr<Formulation> make_formulation(std::string_view name,
                                              std::shared_ptr<const Model> model) {
  const bool gravity_only = model->bodies_are_free() && model->loads.empty();
  if (name == "body") {
    if (gravity_only) return std::make_unique<BodyFrameFormulation>(std::move(model));
    return std::make_unique<ArticulatedFormulation>(
        std::make_shared<const ArticulatedModel>(std::move(model)));
  }
  if (name == "textbook") {
    if (!model->bodies_are_free()) {
      throw std::invalid_argument(
          "formulation textbook integrates free bodies (the chapter's [R; omega]); joints, "
          "springs and impulses need formulation: body");
    }
    return std::make_unique<TextbookFormulation>(std::move(model));
  }
  throw std::invalid_argument("unknown formulation '" + std::string(name) +
                              "'; valid: body, textbook");
}

std::unique_ptr<Formulation> make_formulation(std::string_view name, Model model) {
  return make_formulation(name, std::make_shared<const Model>(std::move(model)));
}

}  // namespace tumble
