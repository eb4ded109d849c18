#include "tumble/math/state_archive.hpp"

#include <limits>

namespace tumble {

void StateArchive::flag(std::string_view key, bool& value) {
  long as_long = value ? 1 : 0;
  integer(key, as_long);
  if (as_long != 0 && as_long != 1) fail(key, "a flag is 0 or 1");
  value = as_long == 1;
}

void StateArchive::integer(std::string_view key, int& value) {
  long as_long = value;
  integer(key, as_long);
  if (as_long < std::numeric_limits<int>::min() || as_long > std::numeric_limits<int>::max()) {
    fail(key, "out of an int's range");
  }
  value = static_cast<int>(as_long);
}

void StateArchive::count(std::string_view key, std::size_t& value) {
  long as_long = static_cast<long>(value);
  integer(key, as_long);
  if (as_long < 0) fail(key, "a count is not negative");
  value = static_cast<std::size_t>(as_long);
}

void StateArchive::vec3(std::string_view key, Vec3& value) {
  VecX as_vector = value;
  numbers(key, as_vector);
  if (as_vector.size() != 3) fail(key, "3 numbers");
  value = as_vector;
}

void StateArchive::mat3(std::string_view key, Mat3& value) {
  VecX as_vector = Eigen::Map<const VecX>(value.data(), 9);
  numbers(key, as_vector);
  if (as_vector.size() != 9) fail(key, "9 numbers");
  value = Eigen::Map<const Mat3>(as_vector.data());
}

void StateArchive::columns(std::string_view key, Eigen::Matrix3Xd& value) {
  VecX as_vector = Eigen::Map<const VecX>(value.data(), value.size());
  numbers(key, as_vector);
  if (as_vector.size() % 3 != 0) fail(key, "columns of 3 numbers");
  value = Eigen::Map<const Eigen::Matrix3Xd>(as_vector.data(), 3, as_vector.size() / 3);
}

}  // namespace tumble
