#include "tumble/simulation/model_from_scenario.hpp"

#include <algorithm>
#include <stdexcept>

namespace tumble {

namespace {

Vec3 com_position_W(const BodySpec& body) {
  return body.position_W + body.R_WB * body.mass_properties.com;
}

}  // namespace

Model build_model(const Scenario& scenario) {
  Model model;
  model.gravity_W = scenario.gravity_W;
  for (const BodySpec& body : scenario.bodies) {
    model.bodies.push_back(RigidBody::make(body.name, body.mass_properties.mass,
                                           body.mass_properties.inertia_about_com));
  }
  for (const LoadSpec& spec : scenario.loads) {
    const auto it = std::find_if(scenario.bodies.begin(), scenario.bodies.end(),
                                 [&](const BodySpec& b) { return b.name == spec.body; });
    if (it == scenario.bodies.end()) {
      throw std::logic_error("load '" + spec.name + "' names no body; the reader checks this");
    }
    AppliedLoad load;
    load.kind =
        spec.kind == LoadSpec::Kind::Force ? AppliedLoad::Kind::Force : AppliedLoad::Kind::Torque;
    load.name = spec.name;
    load.body = static_cast<std::size_t>(it - scenario.bodies.begin());
    load.value = spec.value;
    load.body_frame = spec.body_frame;
    // `at:` is a world point at t = 0; fix it to the body as an offset from the COM in body axes.
    if (spec.has_point) load.p_GP_B = it->R_WB.transpose() * (spec.at_W - com_position_W(*it));
    load.from = spec.from;
    load.to = spec.to;
    model.loads.push_back(load);
  }
  return model;
}

std::vector<BodyState> initial_states(const Scenario& scenario) {
  std::vector<BodyState> states;
  for (const BodySpec& body : scenario.bodies) {
    BodyState s;
    s.r_G = com_position_W(body);
    s.R_WB = body.R_WB;
    s.v_G = body.velocity_W;
    s.omega_W = body.angular_velocity_W;
    states.push_back(s);
  }
  return states;
}

}  // namespace tumble
