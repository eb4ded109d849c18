#include "tumble/dynamics/formulation.hpp"

#include <stdexcept>
#include <string>

#include "tumble/dynamics/body_frame_formulation.hpp"
#include "tumble/dynamics/textbook_formulation.hpp"

namespace tumble {

std::unique_ptr<Formulation> make_formulation(std::string_view name, Model model) {
  if (name == "body") return std::make_unique<BodyFrameFormulation>(std::move(model));
  if (name == "textbook") return std::make_unique<TextbookFormulation>(std::move(model));
  throw std::invalid_argument("unknown formulation '" + std::string(name) +
                              "'; valid: body, textbook");
}

}  // namespace tumble
