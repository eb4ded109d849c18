#include "tumble/input/bounded_read.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <istream>
#include <string_view>

namespace tumble {

std::uint64_t limit_bytes(const ReadLimit& limit) {
  constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;
  constexpr std::uint64_t kLargestMiB = std::uint64_t{1} << 40;  // 2^60 bytes
  const char* set = std::getenv(limit.variable);
  if (set == nullptr || *set == '\0') return limit.default_mib * kMiB;
  const std::string_view text(set);
  std::uint64_t mib = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), mib);
  if (error != std::errc() || end != text.data() + text.size() || mib < 1 || mib > kLargestMiB) {
    throw ReadLimitError(fmt::format(
        "cannot be read: {}={} is not a limit: expected a whole number of MiB from 1 to {} "
        "(unset it for the default, {} MiB)",
        limit.variable, text, kLargestMiB, limit.default_mib));
  }
  return mib * kMiB;
}

std::string too_large_message(const ReadLimit& limit, std::uint64_t size) {
  const std::uint64_t bytes = limit_bytes(limit);
  const std::string how_large =
      size > 0 ? fmt::format("is {} bytes, larger than", size) : "goes on past";
  return fmt::format(
      "{} the limit of {} MiB ({} bytes) for {} (set {} to a larger number of "
      "MiB to raise it)",
      how_large, bytes >> 20, bytes, limit.what, limit.variable);
}

std::string read_bounded(const std::string& path, std::istream& in, const ReadLimit& limit) {
  const std::uint64_t bytes = limit_bytes(limit);
  // A regular file says its size: refused before any byte is read. A device or a FIFO has none
  // (or a false one), so the read below stops one byte past the limit too.
  std::error_code error;
  if (std::filesystem::is_regular_file(path, error)) {
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (!error && size > bytes) throw ReadLimitError(too_large_message(limit, size));
  }
  std::string contents;
  std::array<char, 1 << 16> buffer{};
  while (in) {
    const std::uint64_t room = bytes + 1 - contents.size();
    const std::streamsize want =
        static_cast<std::streamsize>(std::min<std::uint64_t>(buffer.size(), room));
    in.read(buffer.data(), want);
    contents.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
    if (contents.size() > bytes) throw ReadLimitError(too_large_message(limit, 0));
  }
  if (in.bad()) throw std::runtime_error("read error");
  return contents;
}

}  // namespace tumble
