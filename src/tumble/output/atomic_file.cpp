#include "tumble/output/atomic_file.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>
#include <system_error>

namespace tumble {

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
  // A name unique to this process, so two runs writing the same destination do not collide.
  temporary_ = path_;
  temporary_ += fmt::format(".partial-{}", static_cast<long>(::getpid()));
  file_ = std::fopen(temporary_.c_str(), "wb");
  if (file_ == nullptr) {
    throw std::runtime_error(
        fmt::format("cannot write {}: {}", path_.string(), std::generic_category().message(errno)));
  }
}

AtomicFile::~AtomicFile() {
  if (file_ != nullptr) std::fclose(file_);
  if (!renamed_) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
}

void AtomicFile::finish() {
  const bool write_failed = std::ferror(file_) != 0;
  const bool close_failed = std::fclose(file_) != 0;
  file_ = nullptr;
  if (write_failed || close_failed) {
    throw std::runtime_error(fmt::format("error writing {}", path_.string()));
  }
  std::error_code error;
  std::filesystem::rename(temporary_, path_, error);
  if (error) {
    throw std::runtime_error(fmt::format("cannot write {}: {}", path_.string(), error.message()));
  }
  renamed_ = true;
}

}  // namespace tumble
