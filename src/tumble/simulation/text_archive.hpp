#pragma once
// The checkpoint file's text: one field a line, "KEY VALUE", the key naming the field by its
// parts ("hybrid.contact.contacts[0].mode"). A number is written as the shortest decimal that
// reads back as the same double; a vector as its length and then its numbers; text to the end
// of the line, with backslash escapes for a newline and a backslash. A reader takes the lines
// back in the order they were written and names the line and key of anything that does not fit.
#include <string>
#include <string_view>
#include <vector>

#include "tumble/math/state_archive.hpp"

namespace tumble {

class TextArchiveWriter final : public StateArchive {
 public:
  bool loading() const override { return false; }
  std::size_t fields_left() const override { return 0; }
  // Never a load: a field it cannot take is the code's error (std::logic_error).
  [[noreturn]] void fail(std::string_view key, std::string_view why) const override;
  void number(std::string_view key, double& value) override;
  void integer(std::string_view key, long& value) override;
  void numbers(std::string_view key, VecX& values) override;
  void text(std::string_view key, std::string& value) override;
  void enter(std::string_view part) override;
  void leave() override;
  using StateArchive::integer;

  // A line of its own, not a field (a comment for the reader of the file).
  void comment(std::string_view line);
  const std::string& written() const { return out_; }

 private:
  void begin_line(std::string_view key);
  std::string out_;
  std::vector<std::string> parts_;
};

class TextArchiveReader final : public StateArchive {
 public:
  // `file` names the text in messages; the text must outlive the reader.
  TextArchiveReader(std::string_view text, std::string file);
  bool loading() const override { return true; }
  std::size_t fields_left() const override { return lines_.size() - next_; }
  void number(std::string_view key, double& value) override;
  void integer(std::string_view key, long& value) override;
  void numbers(std::string_view key, VecX& values) override;
  void text(std::string_view key, std::string& value) override;
  void enter(std::string_view part) override;
  void leave() override;
  using StateArchive::integer;

  // Whether every field line has been read.
  bool at_end() const { return next_ == lines_.size(); }
  // Throws CheckpointFileError "FILE:LINE: KEY: why" at the line last read (or the next).
  [[noreturn]] void fail(std::string_view key, std::string_view why) const override;

 private:
  // The value of the next field line, which must be `key`'s.
  std::string_view take(std::string_view key);
  std::string full_key(std::string_view key) const;
  struct Line {
    std::size_t number;  // 1-based, in the file
    std::string_view text;
  };
  std::string file_;
  std::vector<Line> lines_;  // the field lines (comments and blank lines left out)
  std::size_t next_ = 0;
  std::vector<std::string> parts_;
};

}  // namespace tumble
