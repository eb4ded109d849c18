// tumble.inertia: what `tumble inertia` prints, as numbers: each body's mass, COM, inertia about
// the COM, principal moments and axes, and (given a point) its inertia about that point.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include <optional>
#include <stdexcept>

#include "bindings.hpp"
#include "tumble/inertia/mass_properties.hpp"

namespace tumble::python {
namespace {

py::dict body_inertia(const BodySpec& body, const std::optional<Vec3>& O_W) {
  const MassProperties& mp = body.mass_properties;
  const PrincipalAxes principal = principal_axes(mp.inertia_about_com);
  py::dict out;
  out["mass"] = mp.mass;
  out["com_body"] = Vec3(mp.com);
  out["com_world"] = Vec3(body.position_W + body.R_WB * mp.com);
  out["inertia_com_body"] = Mat3(mp.inertia_about_com);
  out["principal_moments"] = Vec3(principal.moments);
  out["principal_axes"] = Mat3(principal.axes);  // columns, body axes
  out["given"] = body.inertia_overridden;
  if (O_W) {
    // The parallel axis theorem about a world point at t = 0, in the body's axes, then in the
    // world's: I_O = I_G + m (|d|^2 E - d d^T), d from O to the COM.
    const Vec3 O_B = body.R_WB.transpose() * (*O_W - body.position_W);
    const Mat3 I_O_B = inertia_about_point(mp, O_B);
    out["about"] = *O_W;
    out["inertia_about_body"] = I_O_B;
    out["inertia_about_world"] = Mat3(body.R_WB * I_O_B * body.R_WB.transpose());
    out["principal_moments_about"] = Vec3(principal_axes(I_O_B).moments);
  }
  return out;
}

}  // namespace

void bind_inertia(py::module_& m) {
  m.def(
      "inertia",
      [](const std::string& source, bool is_text, const std::string& name,
         const Overrides& overrides, std::optional<Vec3> about) {
        // As `tumble inertia --about` does: a point of NaN or infinite coordinates is refused,
        // not printed as NaN tensors.
        if (about && !about->allFinite()) {
          throw std::invalid_argument(
              fmt::format("about [{}, {}, {}]: expected three finite numbers (m, world)",
                          (*about)(0), (*about)(1), (*about)(2)));
        }
        const std::vector<ParameterOverride> sets = to_overrides(overrides);
        const Scenario scenario = is_text ? load_scenario_text(source, name, sets, false)
                                          : load_scenario(source, sets, false);
        py::dict bodies;
        for (const BodySpec& body : scenario.bodies) {
          bodies[py::str(body.name)] = body_inertia(body, about);
        }
        return bodies;
      },
      py::arg("source"), py::arg("is_text"), py::arg("name"), py::arg("overrides"),
      py::arg("about").none(true));
}

}  // namespace tumble::python
