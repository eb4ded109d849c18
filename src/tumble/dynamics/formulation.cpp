#include "tumble/dynamics/formulation.hpp"

#include <stdexcept>
#include <string>

#include "tumble/dynamics/body_frame_formulation.hpp"
#include "tumble/dynamics/textbook_formulation.hpp"
#include "tumble/multibody/articulated_formulation.hpp"

namespace tumble {

void Formulation::unpack_all(const VecX& y, std::span<BodyState> states) const {
  for (std::size_t i = 0; i < states.size(); ++i) states[i] = unpack(y, i);
}

void Formulation::calc_row_extras(double /*t*/, const VecX& /*y*/, RowExtras& extras) const {
  extras = RowExtras{};
}

std::unique_ptr<Formulation> make_formulation(std::string_view name, Model model) {
  const bool gravity_only = model.bodies_are_free() && model.loads.empty();
  if (name == "body") {
    if (gravity_only) return std::make_unique<BodyFrameFormulation>(std::move(model));
    return std::make_unique<ArticulatedFormulation>(std::move(model));
  }
  if (name == "textbook") {
    if (!model.bodies_are_free()) {
      throw std::invalid_argument(
          "formulation textbook integrates free bodies (the chapter's [R; omega]); joints, "
          "springs and impulses need formulation: body");
    }
    return std::make_unique<TextbookFormulation>(std::move(model));
  }
  throw std::invalid_argument("unknown formulation '" + std::string(name) +
                              "'; valid: body, textbook");
}

}  // namespace tumble
