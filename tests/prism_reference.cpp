#include "prism_reference.hpp"

#include <yaml-cpp/yaml.h>

#include <stdexcept>

namespace tumble::testing {

namespace {

Vec3 read_vec3(const YAML::Node& n) {
  return Vec3(n[0].as<double>(), n[1].as<double>(), n[2].as<double>());
}

std::vector<PrismCase> load_cases() {
  // The *_str fields carry 35 digits; strtod rounds them to the nearest double.
  const YAML::Node root = YAML::LoadFile(TUMBLE_TEST_DATA_DIR "/free-prism-40digit.json");
  std::vector<PrismCase> cases;
  for (const YAML::Node& c : root["cases"]) {
    PrismCase pc;
    pc.id = c["id"].as<std::string>();
    pc.I0_diag = read_vec3(c["I0_diag"]);
    pc.omega0_W = read_vec3(c["omega0"]);
    pc.energy = std::stod(c["energy_str"].as<std::string>());
    pc.L_norm = std::stod(c["L_norm_str"].as<std::string>());
    for (const YAML::Node& s : c["states"]) {
      ReferenceState rs;
      rs.t = s["t"].as<double>();
      for (int k = 0; k < 3; ++k) {
        rs.omega_W(k) = std::stod(s["omega_spatial_str"][k].as<std::string>());
        rs.omega_B(k) = std::stod(s["omega_body_str"][k].as<std::string>());
      }
      for (int k = 0; k < 9; ++k)
        rs.R_WB(k / 3, k % 3) = std::stod(s["R_str"][k].as<std::string>());
      pc.states.push_back(rs);
    }
    cases.push_back(pc);
  }
  return cases;
}

}  // namespace

const std::vector<PrismCase>& prism_cases() {
  static const std::vector<PrismCase> cases = load_cases();
  return cases;
}

const PrismCase& prism_case(const std::string& id) {
  for (const PrismCase& c : prism_cases()) {
    if (c.id == id) return c;
  }
  throw std::invalid_argument("no prism case " + id);
}

Model prism_model(const PrismCase& c) {
  Model model;
  model.gravity_W.setZero();
  model.bodies.push_back(RigidBody::make("prism", 12.0, c.I0_diag.asDiagonal()));
  return model;
}

BodyState prism_initial_state(const PrismCase& c) {
  BodyState s;
  s.omega_W = c.omega0_W;
  return s;
}

double state_error(const Mat3& R, const Vec3& omega_W, const ReferenceState& ref) {
  return std::max((R - ref.R_WB).cwiseAbs().maxCoeff(),
                  (omega_W - ref.omega_W).cwiseAbs().maxCoeff());
}

}  // namespace tumble::testing
