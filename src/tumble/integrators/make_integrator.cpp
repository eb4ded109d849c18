#include <memory>
#include <stdexcept>
#include <string>

#include "tumble/integrators/auto_switching.hpp"
#include "tumble/integrators/dop853.hpp"
#include "tumble/integrators/dopri5.hpp"
#include "tumble/integrators/integrator.hpp"
#include "tumble/integrators/radau5.hpp"
#include "tumble/integrators/rk4.hpp"
#include "tumble/integrators/rkmk4.hpp"
#include "tumble/integrators/trbdf2.hpp"

namespace tumble {

std::unique_ptr<Integrator> make_integrator(std::string_view name, const StepControl& control) {
  if (name == "dopri5") return std::make_unique<Dopri5>(control);
  if (name == "dop853") return std::make_unique<Dop853>(control);
  if (name == "rk4") return std::make_unique<Rk4>(control);
  if (name == "rkmk4") return std::make_unique<Rkmk4>(control);
  if (name == "radau5") return std::make_unique<Radau5>(control);
  if (name == "trbdf2") return std::make_unique<TrBdf2>(control);
  if (name == "auto") return std::make_unique<AutoSwitching>(control);
  throw std::invalid_argument("unknown integrator '" + std::string(name) +
                              "'; valid names: dopri5, dop853, rk4, rkmk4, radau5, trbdf2, auto");
}

}  // namespace tumble
