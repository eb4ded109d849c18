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
  // (and removes the temporary file). After publish(), flushes and closes only.
  void finish();
  // Renames the file into place now, with what has been written so far, and keeps it open: what
  // is written later goes on the published file (a sweep's rows as they finish, each whole line
  // flushed, so that a sweep stopped at any point leaves a valid file of the rows so far).
  // Throws std::runtime_error on an I/O error.
  void publish();
  // Hands what has been written to the file system. Throws std::runtime_error on an I/O error.
  void flush();

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::filesystem::path temporary_;
  std::FILE* file_ = nullptr;
  bool renamed_ = false;
  std::size_t signal_slot_ = static_cast<std::size_t>(-1);  // none: the stop handler's entry
};

// Copies `made`, a finished file a helper program wrote into a directory of tumble's own (a
// figure, a video), to `destination` through an AtomicFile: the destination's folder sees only
// the safe temporary name and the final rename. Throws std::runtime_error naming the file.
void install_copy(const std::filesystem::path& made, const std::filesystem::path& destination);

}  // namespace tumble
