#include "tumble/output/trajectory_csv.hpp"

#include <stdexcept>

namespace tumble {

std::vector<std::string> trajectory_columns(std::span<const std::string> body_names,
                                            std::span<const std::string> joint_names,
                                            std::span<const std::string> contact_names,
                                            std::span<const std::string> element_names) {
  std::vector<std::string> columns{"t"};
  static const char* const kBodyFields[] = {"x",   "y",   "z",   "vx",  "vy",  "vz",
                                            "wx",  "wy",  "wz",  "R11", "R12", "R13",
                                            "R21", "R22", "R23", "R31", "R32", "R33"};
  for (const std::string& body : body_names) {
    for (const char* field : kBodyFields) columns.push_back(body + "." + field);
  }
  for (const char* c : {"KE", "PE", "E", "px", "py", "pz", "Lx", "Ly", "Lz"}) {
    columns.emplace_back(c);
  }
  for (const std::string& joint : joint_names) {
    for (const char* field : {"Fx", "Fy", "Fz", "Mx", "My", "Mz"}) {
      columns.push_back(joint + "." + field);
    }
  }
  for (const std::string& contact : contact_names) {
    for (const char* field : {"N", "Fx", "Fy", "Fz", "slip", "mode"}) {
      columns.push_back(contact + "." + field);
    }
  }
  for (const std::string& element : element_names) {
    columns.push_back(element + ".P");
    columns.push_back(element + ".W");
  }
  return columns;
}

TrajectoryCsvWriter::TrajectoryCsvWriter(std::filesystem::path path,
                                         std::span<const std::string> body_names,
                                         std::span<const std::string> joint_names,
                                         std::span<const std::string> contact_names,
                                         std::span<const std::string> element_names)
    : file_(std::move(path)) {
  const std::vector<std::string> columns =
      trajectory_columns(body_names, joint_names, contact_names, element_names);
  fmt::memory_buffer header;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    fmt::format_to(std::back_inserter(header), "{}{}", i == 0 ? "" : ",", columns[i]);
  }
  header.push_back('\n');
  file_.write(std::string_view(header.data(), header.size()));
}

void TrajectoryCsvWriter::write_row(double t, std::span<const BodyState> states,
                                    const SystemQuantities& q, const RowExtras* extras) {
  line_.clear();
  auto out = std::back_inserter(line_);
  fmt::format_to(out, "{:.17g}", t);
  const auto put = [&](double v) { fmt::format_to(out, ",{:.17g}", v); };
  for (const BodyState& s : states) {
    for (int k = 0; k < 3; ++k) put(s.r_G(k));
    for (int k = 0; k < 3; ++k) put(s.v_G(k));
    for (int k = 0; k < 3; ++k) put(s.omega_W(k));
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) put(s.R_WB(r, c));
    }
  }
  put(q.kinetic_energy);
  put(q.potential_energy);
  put(q.total_energy);
  for (int k = 0; k < 3; ++k) put(q.linear_momentum(k));
  for (int k = 0; k < 3; ++k) put(q.angular_momentum_about_origin(k));
  if (extras != nullptr) {
    for (const JointReaction& joint : extras->joints) {
      for (int k = 0; k < 3; ++k) put(joint.F_W(k));
      for (int k = 0; k < 3; ++k) put(joint.M_J_W(k));
    }
    for (const ContactOutput& contact : extras->contacts) {
      put(contact.normal_force);
      for (int k = 0; k < 3; ++k) put(contact.friction_W(k));
      put(contact.slip_speed);
      fmt::format_to(out, ",{}", contact.mode);
    }
    for (const ElementWork& element : extras->elements) {
      put(element.power);
      put(element.work);
    }
  }
  line_.push_back('\n');
  file_.write(std::string_view(line_.data(), line_.size()));
  ++rows_;
}

void TrajectoryCsvWriter::finish() {
  file_.finish();
}

}  // namespace tumble
