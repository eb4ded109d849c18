#pragma once
// An output file that appears only when complete: it is written under a temporary name beside
// its destination (same file system, so the final rename is atomic) and renamed by finish();
// destroyed unfinished, it removes the temporary file and leaves nothing behind. A run stopped by
// SIGINT, SIGTERM or SIGHUP while it writes removes the temporary file too. The temporary file is
// created new (O_CREAT | O_EXCL | O_NOFOLLOW) under a name with a random part: in a directory
// that others can write, a file or symlink planted at any name is never opened, so tumble cannot
// be made to write through it.
#include <cstdio>
#include <filesystem>
#include <span>
#include <string_view>

namespace tumble {

class AtomicFile {
 public:
  // Throws std::runtime_error naming the destination if the temporary file cannot be created.
  explicit AtomicFile(std::filesystem::path path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  void write(std::string_view text) { std::fwrite(text.data(), 1, text.size(), file_); }
  void write(std::span<const std::string_view> chunks) {
    for (const std::string_view chunk : chunks) write(chunk);
  }
  // Flushes, closes and renames to the destination. Throws std::runtime_error on an I/O error
  // (and removes the temporary file).
  void finish();

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::FILE* file_ = nullptr;
  bool renamed_ = false;
  std::size_t signal_slot_ = static_cast<std::size_t>(-1);  // none: the stop handler's entry
};

}  // namespace tumble
