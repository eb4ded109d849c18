#include "tumble/scenario/yaml_reader.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <limits>

namespace tumble::scenario_reading {
namespace {

// What a node holds, for "expected ..., got ..." messages.
std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined:
      return "nothing";
    case YAML::NodeType::Scalar:
      return "'" + node.Scalar() + "'";
    case YAML::NodeType::Sequence:
      return "a list of " + std::to_string(node.size());
    case YAML::NodeType::Map:
      return "a mapping";
  }
  return "something else";
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      current[j] =
          std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (same ? 0 : 1)});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

// The offset of the first byte that breaks UTF-8 (a stray byte, a truncated or overlong sequence,
// a surrogate, past U+10FFFF), or npos if the text is valid.
std::size_t first_invalid_utf8(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(i);
    std::size_t length = 0;
    std::uint32_t code = 0, least = 0;
    if (lead < 0x80) {
      ++i;
      continue;
    } else if ((lead & 0xE0) == 0xC0) {
      length = 2, code = lead & 0x1F, least = 0x80;
    } else if ((lead & 0xF0) == 0xE0) {
      length = 3, code = lead & 0x0F, least = 0x800;
    } else if ((lead & 0xF8) == 0xF0) {
      length = 4, code = lead & 0x07, least = 0x10000;
    } else {
      return i;
    }
    if (i + length > text.size()) return i;
    for (std::size_t k = 1; k < length; ++k) {
      if ((byte(i + k) & 0xC0) != 0x80) return i;
      code = (code << 6) | (byte(i + k) & 0x3F);
    }
    if (code < least || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return i;
    i += length;
  }
  return std::string_view::npos;
}

Field item_field(const Field& list, const YAML::Node& item, std::size_t index) {
  return Field{item, list.path + "[" + std::to_string(index) + "]",
               item.Mark().is_null() ? list.value_mark() : item.Mark()};
}

}  // namespace

YAML::Mark Field::value_mark() const {
  if (node && !node.IsNull() && !node.Mark().is_null()) return node.Mark();
  return key_mark;
}

std::string Field::key() const {
  const auto dot = path.find_last_of('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

std::string format_number(double value) {
  return fmt::format("{}", value);
}

std::optional<Vec3> unit_direction(const Vec3& v) {
  const double largest = v.cwiseAbs().maxCoeff();
  if (!(largest > 0.0)) return std::nullopt;
  // Scaled only where the square of the norm would overflow or underflow: otherwise the unit
  // vector is v.normalized()'s, bit for bit, as it always was.
  const double squared = v.squaredNorm();
  if (std::isfinite(squared) && squared >= std::numeric_limits<double>::min()) {
    return v.normalized();
  }
  return Vec3(v / largest).normalized();
}

std::string printable(std::string_view text) {
  std::string shown;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7F) {
      shown += fmt::format("\\x{:02X}", byte);
    } else {
      shown += c;
    }
  }
  return shown;
}

std::string join(const std::vector<std::string>& words, std::string_view separator) {
  return fmt::format("{}", fmt::join(words, separator));
}

std::optional<std::string> closest_match(std::string_view word,
                                         const std::vector<std::string>& candidates) {
  // A typo is a slip of a letter or two; a short word may differ by one only.
  const std::size_t limit = word.size() <= 4 ? 1 : (word.size() <= 8 ? 2 : 3);
  std::optional<std::string> best;
  std::size_t best_distance = limit + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t distance = edit_distance(word, candidate);
    if (distance < best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  return best;
}

SourceLocation Reader::location(const YAML::Mark& mark) const {
  if (mark.is_null()) return SourceLocation{file_, 0, 0};
  return SourceLocation{file_, mark.line + 1, mark.column + 1};
}

void Reader::fail(const YAML::Mark& mark, const std::string& key, const std::string& why) const {
  throw ScenarioError(location(mark), key, why);
}

double Reader::angle(const Field& field) const {
  const double value = number(field);
  const std::string written = field.node.Scalar();
  const bool says_unit =
      written.find("deg") != std::string::npos || written.find("pi") != std::string::npos;
  if (std::abs(value) > 2.0 * std::numbers::pi && !says_unit) {
    warn(field, fmt::format("the angle {} is read in radians ({:.4g} degrees, more than a turn); "
                            "write '{} deg' if degrees were meant",
                            written, value * 180.0 / std::numbers::pi, written));
  }
  return value;
}

void Reader::warn(const Field& field, const std::string& why) const {
  if (warnings_ == nullptr) return;
  warnings_->push_back(ScenarioError(location(field.value_mark()), field.path, why).what());
}

double Reader::number(const Field& field) const {
  if (!field.node || !field.node.IsScalar()) {
    fail_at_value(field, "expected a number or an expression, got " + describe(field.node));
  }
  double value = 0.0;
  try {
    value = expressions_->evaluate(field.node.Scalar());
  } catch (const ExpressionError& error) {
    fail_at_value(field, error.what());
  }
  if (trace_ != nullptr) trace_->note(field.path, field.node.Scalar());
  return value;
}

std::vector<double> Reader::numbers(const Field& field, std::size_t count,
                                    std::string_view form) const {
  if (!field.node || !field.node.IsSequence() || field.node.size() != count) {
    fail_at_value(field, fmt::format("expected a list of {} numbers {}, got {}", count, form,
                                     describe(field.node)));
  }
  std::vector<double> values;
  for (const Field& item : items(field, form)) values.push_back(number(item));
  return values;
}

Vec3 Reader::vec3(const Field& field) const {
  const std::vector<double> v = numbers(field, 3, "[x, y, z]");
  return Vec3(v[0], v[1], v[2]);
}

Vec3 Reader::point_or_vector(const Field& field) const {
  if (!planar_) return vec3(field);
  const std::vector<double> v =
      numbers(field, 2, "[x, y] (the scenario is planar: points and vectors lie in its x-y plane)");
  return Vec3(v[0], v[1], 0.0);
}

std::pair<Vec3, Vec3> Reader::two_points(const Field& field) const {
  const std::vector<Field> points = items(field, "of two points [[x, y, z], [x, y, z]]");
  if (points.size() != 2) {
    fail_at_value(field, fmt::format("give two points, one on each body; got {}", points.size()));
  }
  return {point_or_vector(points[0]), point_or_vector(points[1])};
}

Vec3 Reader::spin_vector(const Field& field) const {
  if (!planar_) return vec3(field);
  if (!field.node || !field.node.IsScalar()) {
    fail_at_value(field,
                  "expected one number (the scenario is planar: turning is about z, "
                  "counter-clockwise seen from +z), got " +
                      describe(field.node));
  }
  return Vec3(0.0, 0.0, number(field));
}

Mat3 Reader::mat3(const Field& field) const {
  constexpr std::string_view form = "[[r11, r12, r13], [r21, r22, r23], [r31, r32, r33]]";
  if (!field.node || !field.node.IsSequence() || field.node.size() != 3) {
    fail_at_value(field,
                  fmt::format("expected a 3x3 matrix {}, got {}", form, describe(field.node)));
  }
  Mat3 m;
  const std::vector<Field> rows = items(field, form);
  for (int row = 0; row < 3; ++row) {
    const std::vector<double> v = numbers(rows[static_cast<std::size_t>(row)], 3, "(a matrix row)");
    for (int col = 0; col < 3; ++col) m(row, col) = v[static_cast<std::size_t>(col)];
  }
  return m;
}

std::string Reader::text(const Field& field) const {
  if (!field.node || !field.node.IsScalar()) {
    fail_at_value(field, "expected a word or text, got " + describe(field.node));
  }
  // Text reaches the CSV's header, the summary and the animation page, which must be UTF-8.
  const std::string& value = field.node.Scalar();
  if (const std::size_t at = first_invalid_utf8(value); at != std::string_view::npos) {
    fail_at_value(field, fmt::format("the text is not valid UTF-8 (byte 0x{:02X} at its position "
                                     "{}); save the file as UTF-8",
                                     static_cast<unsigned char>(value[at]), at + 1));
  }
  return value;
}

std::vector<Field> Reader::items(const Field& field, std::string_view form) const {
  if (!field.node || !field.node.IsSequence()) {
    fail_at_value(field, fmt::format("expected a list {}, got {}", form, describe(field.node)));
  }
  std::vector<Field> result;
  for (std::size_t i = 0; i < field.node.size(); ++i) {
    result.push_back(item_field(field, field.node[i], i));
  }
  return result;
}

MapReader::MapReader(const Reader& reader, Field self, std::string_view form)
    : reader_(&reader), self_(std::move(self)) {
  if (!self_.node || !self_.node.IsMap()) {
    reader.fail_at_value(self_, fmt::format("expected {}, got {}", form, describe(self_.node)));
  }
  for (const auto& entry : self_.node) {
    // Copies: the iterator's pair is a temporary.
    const YAML::Node key = entry.first;
    const YAML::Node value = entry.second;
    if (!key.IsScalar()) {
      reader.fail(key.Mark(), self_.path, "a key must be a plain word, got " + describe(key));
    }
    // Keys name bodies, joints and parameters, and so head CSV columns and reach the page.
    if (const std::size_t at = first_invalid_utf8(key.Scalar()); at != std::string_view::npos) {
      reader.fail(key.Mark(), self_.path,
                  fmt::format("a key is not valid UTF-8 (byte 0x{:02X} at its position {}); save "
                              "the file as UTF-8",
                              static_cast<unsigned char>(key.Scalar()[at]), at + 1));
    }
    const std::string path = self_.path.empty() ? key.Scalar() : self_.path + "." + key.Scalar();
    Field field{value, path, key.Mark()};
    const auto [earlier, fresh] = index_.emplace(key.Scalar(), fields_.size());
    if (!fresh) {
      reader.fail_at_key(field,
                         fmt::format("duplicate key '{}' (first given on line {}); "
                                     "give each key once",
                                     key.Scalar(), fields_[earlier->second].key_mark.line + 1));
    }
    fields_.push_back(std::move(field));
  }
}

std::optional<Field> MapReader::find(std::string_view key) const {
  const auto at = index_.find(std::string(key));
  if (at == index_.end()) return std::nullopt;
  return fields_[at->second];
}

Field MapReader::require(std::string_view key, std::string_view purpose) const {
  if (std::optional<Field> field = find(key)) return *field;
  const std::string path =
      self_.path.empty() ? std::string(key) : self_.path + "." + std::string(key);
  reader_->fail(self_.key_mark, path, fmt::format("missing required key '{}' ({})", key, purpose));
}

void MapReader::allow_only(const std::vector<std::string>& allowed, std::string_view what,
                           const std::function<std::string(const std::string&)>& explain) const {
  for (const Field& field : fields_) {
    const std::string key = field.key();
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    if (explain) {
      const std::string reason = explain(key);
      if (!reason.empty()) reader_->fail_at_key(field, reason);
    }
    std::string why = "unknown key '" + key + "'";
    if (const auto match = closest_match(key, allowed)) why += "; did you mean '" + *match + "'?";
    why += fmt::format(" ({} takes: {})", what, join(allowed));
    reader_->fail_at_key(field, why);
  }
}

}  // namespace tumble::scenario_reading
