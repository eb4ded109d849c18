#pragma once
// A run's state field by field, for a checkpoint file: each struct or method lists its fields
// once, in one function over a StateArchive, and that one function both saves them (an archive
// that writes) and loads them (one that reads back, in the same order). Saving and loading cannot
// disagree on a field, and a field left out is left out of both.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "tumble/math/types.hpp"

namespace tumble {

class StateArchive {
 public:
  virtual ~StateArchive() = default;

  // Whether this archive reads (a load sets every field it visits) or writes.
  virtual bool loading() const = 0;

  // The primitive fields: a number exactly (the saved double's bits come back), an integer, a
  // vector of numbers (resized to the saved length on a load), a line of text.
  virtual void number(std::string_view key, double& value) = 0;
  virtual void integer(std::string_view key, long& value) = 0;
  virtual void numbers(std::string_view key, VecX& values) = 0;
  virtual void text(std::string_view key, std::string& value) = 0;

  // Throws for a value a load cannot take, naming where it is (a reader: the file, line and
  // key).
  [[noreturn]] virtual void fail(std::string_view key, std::string_view why) const = 0;

  // A load's bound on a list's length: the fields still to read (each item has one at least).
  virtual std::size_t fields_left() const = 0;

  // Fields of a part: their keys are "part.key" (nested parts join with dots).
  virtual void enter(std::string_view part) = 0;
  virtual void leave() = 0;

  // The rest, on those.
  void flag(std::string_view key, bool& value);
  void integer(std::string_view key, int& value);
  void count(std::string_view key, std::size_t& value);
  void vec3(std::string_view key, Vec3& value);
  void mat3(std::string_view key, Mat3& value);
  void columns(std::string_view key, Eigen::Matrix3Xd& value);  // 3 x n, column after column
  // An enumerator from the first (0) to `last` (a load refuses any other number).
  template <typename Enum>
  void choice(std::string_view key, Enum& value, Enum last) {
    const int count = static_cast<int>(last) + 1;
    int as_int = static_cast<int>(value);
    integer(key, as_int);
    if (as_int < 0 || as_int >= count) {
      fail(key, "not one of the " + std::to_string(count) + " choices");
    }
    value = static_cast<Enum>(as_int);
  }
  // On a load, fails at `key` (the field just read) unless `holds`; `what` says what it must be.
  void require(std::string_view key, bool holds, std::string_view what) const {
    if (loading() && !holds) fail(key, what);
  }
  // A list: its length, then each item's fields under "key[i]" by visit(archive, item).
  template <typename T, typename Visit>
  void list(std::string_view key, std::vector<T>& items, const Visit& visit) {
    std::size_t size = items.size();
    count(std::string(key) + ".size", size);
    if (loading()) {
      if (size > fields_left()) fail(std::string(key) + ".size", "more items than fields are left");
      items.resize(size);
    }
    for (std::size_t i = 0; i < size; ++i) {
      enter(std::string(key) + "[" + std::to_string(i) + "]");
      visit(*this, items[i]);
      leave();
    }
  }
};

}  // namespace tumble
