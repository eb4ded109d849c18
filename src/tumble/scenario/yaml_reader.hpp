#pragma once
// Typed reading of a scenario's YAML with the place of every value: numbers (as expressions),
// 3-vectors, 3x3 matrices, text, lists and mappings whose keys are checked against the keys they
// may hold. Every failure is a ScenarioError at FILE:LINE:COL with the dotted key path.
#include <yaml-cpp/yaml.h>

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "tumble/math/types.hpp"
#include "tumble/scenario/expression.hpp"
#include "tumble/scenario/parameter_trace.hpp"
#include "tumble/scenario/scenario.hpp"

namespace tumble::scenario_reading {

// A value of the file: its node, its dotted key path ("bodies.prism.mass", "forces[2].value"; ""
// for the whole file) and where its key starts (for a list item: where the item starts).
struct Field {
  YAML::Node node;
  std::string path;
  YAML::Mark key_mark;

  // Where the value starts; the key's place when the value is empty.
  YAML::Mark value_mark() const;
  // The last component of the path: "mass" for "bodies.prism.mass".
  std::string key() const;
};

// A number for messages: the shortest text that reads back as the same double ("-2", "0.1").
std::string format_number(double value);
// The text with each control character (below 0x20, and 0x7F) written \xNN: text from a file, as
// a message can show it on one clean line without acting on the terminal.
std::string printable(std::string_view text);
// The direction of v as a unit vector, v scaled by its largest component first: [0, 1e300,
// 1e300] is (0, 1, 1) / sqrt(2), not an overflow to infinity; empty for a zero vector.
std::optional<Vec3> unit_direction(const Vec3& v);
// "a, b, c"
std::string join(const std::vector<std::string>& words, std::string_view separator = ", ");
// The candidate closest to `word` by edit distance, if it is close enough to be a likely typo.
std::optional<std::string> closest_match(std::string_view word,
                                         const std::vector<std::string>& candidates);

class Reader {
 public:
  // Warnings (what is accepted but likely not meant) go to `warnings`, if given, as
  // "FILE:LINE:COL: KEY: why". Each number that uses a parameter `trace` follows is noted there.
  Reader(std::string file, const ExpressionEvaluator& expressions,
         std::vector<std::string>* warnings = nullptr, ParameterTrace* trace = nullptr)
      : file_(std::move(file)), expressions_(&expressions), warnings_(warnings), trace_(trace) {}

  const std::string& file() const { return file_; }
  ParameterTrace* trace() const { return trace_; }
  SourceLocation location(const YAML::Mark& mark) const;

  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& key,
                         const std::string& why) const;
  [[noreturn]] void fail_at_value(const Field& field, const std::string& why) const {
    fail(field.value_mark(), field.path, why);
  }
  [[noreturn]] void fail_at_key(const Field& field, const std::string& why) const {
    fail(field.key_mark, field.path, why);
  }

  // A number or an expression over the parameters.
  double number(const Field& field) const;
  // An angle, rad: a number; one beyond 2 pi written without `deg` or `pi` (a bare `25`, or a
  // parameter) is read in radians, with a warning that says so.
  double angle(const Field& field) const;
  void warn(const Field& field, const std::string& why) const;
  // A list of exactly `count` numbers; `form` names the expected form in messages ("[x, y, z]").
  std::vector<double> numbers(const Field& field, std::size_t count, std::string_view form) const;
  Vec3 vec3(const Field& field) const;
  // A planar scenario (`planar: true`) moves in the world's x-y plane, z out of it.
  void set_planar(bool planar) { planar_ = planar; }
  bool planar() const { return planar_; }
  // The bodies' names, once `bodies:` is read: the joints, forces and contacts that name a body
  // find it in constant time, so that reading stays linear in their number.
  void index_body(const std::string& name, std::size_t position) {
    body_positions_.emplace(name, position);
  }
  // The body's position in `bodies:`, if there is one of that name.
  std::optional<std::size_t> body_position(const std::string& name) const {
    const auto it = body_positions_.find(name);
    if (it == body_positions_.end()) return std::nullopt;
    return it->second;
  }
  // A point or a direction of the world or a body: [x, y, z]; in a planar scenario [x, y], in
  // the plane (z = 0).
  Vec3 point_or_vector(const Field& field) const;
  // Two points, the first on a spring's or a rod's first body and the second on its second:
  // [[x, y, z], [x, y, z]] (planar: [[x, y], [x, y]]).
  std::pair<Vec3, Vec3> two_points(const Field& field) const;
  // An angular velocity or a torque: [x, y, z]; in a planar scenario one number, about z (counter-
  // clockwise seen from +z).
  Vec3 spin_vector(const Field& field) const;
  // [[r11, r12, r13], [r21, r22, r23], [r31, r32, r33]]
  Mat3 mat3(const Field& field) const;
  // A scalar, as written.
  std::string text(const Field& field) const;
  // The items of a list, each with its path "key[i]".
  std::vector<Field> items(const Field& field, std::string_view form) const;

 private:
  std::string file_;
  const ExpressionEvaluator* expressions_;
  std::vector<std::string>* warnings_;
  ParameterTrace* trace_;
  bool planar_ = false;
  std::unordered_map<std::string, std::size_t> body_positions_;
};

// A mapping of the file. Construction fails unless the value is a mapping with distinct scalar
// keys; `form` describes the expected mapping for that message ("a body {shape: ..., mass: ...}").
class MapReader {
 public:
  MapReader(const Reader& reader, Field self, std::string_view form);

  const Field& self() const { return self_; }
  const std::vector<Field>& fields() const { return fields_; }  // file order
  std::optional<Field> find(std::string_view key) const;
  bool has(std::string_view key) const { return find(key).has_value(); }
  // Fails at this mapping's key when `key` is absent; `purpose` says what the key gives.
  Field require(std::string_view key, std::string_view purpose) const;

  // Fails at the first key that is not in `allowed`. `explain` may give the reason a known key is
  // out of place ("a box takes size, not radius"); otherwise the message suggests the closest
  // allowed key and lists them all, as "what takes: ...".
  void allow_only(const std::vector<std::string>& allowed, std::string_view what,
                  const std::function<std::string(const std::string&)>& explain = {}) const;

 private:
  const Reader* reader_;
  Field self_;
  std::vector<Field> fields_;
  // Each key's position in fields_: duplicates are found, and keys looked up, in constant time,
  // so a mapping of n keys is read in O(n) (a file of 200,000 keys is refused at once).
  std::unordered_map<std::string, std::size_t> index_;
};

}  // namespace tumble::scenario_reading
