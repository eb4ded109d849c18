#include "tumble/simulation/text_archive.hpp"

#include <fmt/core.h>

#include <charconv>
#include <stdexcept>
#include <system_error>

#include "tumble/simulation/checkpoint_file.hpp"

namespace tumble {

namespace {

std::string joined(const std::vector<std::string>& parts, std::string_view key) {
  std::string out;
  for (const std::string& part : parts) {
    out += part;
    out += '.';
  }
  out += key;
  if (key.empty() && !out.empty()) out.pop_back();  // the part itself
  return out;
}

// The first space-separated token of `rest`, taken off it.
std::string_view take_token(std::string_view& rest) {
  const std::size_t end = rest.find(' ');
  const std::string_view token = rest.substr(0, end);
  rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
  return token;
}

bool parse_double(std::string_view token, double& value) {
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end && !token.empty();
}

bool parse_long(std::string_view token, long& value) {
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end && !token.empty();
}

}  // namespace

void TextArchiveWriter::begin_line(std::string_view key) {
  out_ += joined(parts_, key);
  out_ += ' ';
}

void TextArchiveWriter::number(std::string_view key, double& value) {
  begin_line(key);
  out_ += fmt::format("{}\n", value);  // the shortest decimal that reads back as `value`
}

void TextArchiveWriter::integer(std::string_view key, long& value) {
  begin_line(key);
  out_ += fmt::format("{}\n", value);
}

void TextArchiveWriter::numbers(std::string_view key, VecX& values) {
  begin_line(key);
  out_ += fmt::format("{}", values.size());
  for (const double v : values) out_ += fmt::format(" {}", v);
  out_ += '\n';
}

void TextArchiveWriter::text(std::string_view key, std::string& value) {
  begin_line(key);
  for (const char c : value) {
    if (c == '\\') {
      out_ += "\\\\";
    } else if (c == '\n') {
      out_ += "\\n";
    } else {
      out_ += c;
    }
  }
  out_ += '\n';
}

void TextArchiveWriter::fail(std::string_view key, std::string_view why) const {
  throw std::logic_error(fmt::format("{}: {}", joined(parts_, key), why));
}

void TextArchiveWriter::enter(std::string_view part) {
  parts_.emplace_back(part);
}

void TextArchiveWriter::leave() {
  parts_.pop_back();
}

void TextArchiveWriter::comment(std::string_view line) {
  out_ += "# ";
  out_ += line;
  out_ += '\n';
}

TextArchiveReader::TextArchiveReader(std::string_view text, std::string file)
    : file_(std::move(file)) {
  std::size_t number = 0;
  while (!text.empty()) {
    ++number;
    const std::size_t end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    if (!line.empty() && line.front() != '#') lines_.push_back({number, line});
  }
}

std::string TextArchiveReader::full_key(std::string_view key) const {
  return joined(parts_, key);
}

void TextArchiveReader::fail(std::string_view key, std::string_view why) const {
  const std::size_t line = next_ == 0               ? 0
                           : next_ <= lines_.size() ? lines_[next_ - 1].number
                                                    : lines_.back().number;
  throw CheckpointFileError(fmt::format("{}:{}: {}: {}", file_, line, full_key(key), why));
}

std::string_view TextArchiveReader::take(std::string_view key) {
  const std::string expected = full_key(key);
  if (next_ == lines_.size()) fail(key, "the file ends before this field: it is cut short");
  const Line& line = lines_[next_++];
  std::string_view rest = line.text;
  const std::string_view found = take_token(rest);
  if (found != expected) {
    fail(key, fmt::format("expected this field here, found '{}'", found));
  }
  return rest;
}

void TextArchiveReader::number(std::string_view key, double& value) {
  const std::string_view rest = take(key);
  if (!parse_double(rest, value)) fail(key, fmt::format("'{}' is not a number", rest));
}

void TextArchiveReader::integer(std::string_view key, long& value) {
  const std::string_view rest = take(key);
  if (!parse_long(rest, value)) fail(key, fmt::format("'{}' is not an integer", rest));
}

void TextArchiveReader::numbers(std::string_view key, VecX& values) {
  std::string_view rest = take(key);
  long size = 0;
  const std::string_view size_token = take_token(rest);
  if (!parse_long(size_token, size) || size < 0) {
    fail(key, fmt::format("'{}' is not a vector's length", size_token));
  }
  if (static_cast<std::size_t>(size) > (rest.size() + 1) / 2) {  // "v v v": 2 n - 1 characters
    fail(key, fmt::format("fewer numbers on the line than its length, {}", size));
  }
  values.resize(size);
  for (long i = 0; i < size; ++i) {
    const std::string_view token = take_token(rest);
    if (!parse_double(token, values[i])) {
      fail(key, fmt::format("number {} of {}: '{}' is not a number", i + 1, size, token));
    }
  }
  if (!rest.empty()) fail(key, fmt::format("more than the {} numbers its length says", size));
}

void TextArchiveReader::text(std::string_view key, std::string& value) {
  const std::string_view rest = take(key);
  value.clear();
  for (std::size_t i = 0; i < rest.size(); ++i) {
    if (rest[i] != '\\') {
      value += rest[i];
    } else if (i + 1 < rest.size() && (rest[i + 1] == '\\' || rest[i + 1] == 'n')) {
      value += rest[++i] == 'n' ? '\n' : '\\';
    } else {
      fail(key, "a backslash that is not \\\\ or \\n");
    }
  }
}

void TextArchiveReader::enter(std::string_view part) {
  parts_.emplace_back(part);
}

void TextArchiveReader::leave() {
  parts_.pop_back();
}

}  // namespace tumble
