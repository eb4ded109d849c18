#include "tumble/output/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <random>
#include <stdexcept>
#include <system_error>

namespace tumble {

namespace {

// The temporary files being written, for the signal handler: a run stopped by Ctrl-C or a kill
// removes them as a failed one does (only unlink(), which is async-signal-safe, runs there).
// Runs on several threads write files at once, so a slot is claimed by an atomic exchange (free
// -> claimed), filled, then published (live); lock-free atomics are safe in a signal handler.
constexpr std::size_t kLiveFiles = 8;
constexpr std::size_t kPathBytes = 4096;
enum SlotState : int { kFree = 0, kClaimed = 1, kLive = 2 };
char g_live_paths[kLiveFiles][kPathBytes];
std::array<std::atomic<int>, kLiveFiles> g_live = {};
static_assert(std::atomic<int>::is_always_lock_free);
constexpr std::array<int, 3> kStopSignals = {SIGINT, SIGTERM, SIGHUP};

extern "C" void remove_partial_files(int signal_number) {
  for (std::size_t i = 0; i < kLiveFiles; ++i) {
    if (g_live[i].load(std::memory_order_acquire) == kLive) ::unlink(g_live_paths[i]);
  }
  // Then end as the signal would have: the caller sees the same status.
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

// Installs the handler for the stop signals whose action is still the default (a command that
// handles them itself, as the video export does while its child runs, is left alone).
void install_handler_once() {
  static const bool installed = [] {
    for (const int signal_number : kStopSignals) {
      struct sigaction current {};
      ::sigaction(signal_number, nullptr, &current);
      if (current.sa_handler != SIG_DFL) continue;
      struct sigaction action {};
      action.sa_handler = remove_partial_files;
      sigemptyset(&action.sa_mask);
      ::sigaction(signal_number, &action, nullptr);
    }
    return true;
  }();
  (void)installed;
}

// The slot the path now holds, or kLiveFiles if none is free or the path is too long (then a
// stop leaves that file behind, as before).
std::size_t hold_for_signals(const std::filesystem::path& path) {
  const std::string& text = path.native();
  if (text.size() >= kPathBytes) return kLiveFiles;
  for (std::size_t i = 0; i < kLiveFiles; ++i) {
    int expected = kFree;
    if (!g_live[i].compare_exchange_strong(expected, kClaimed, std::memory_order_acquire)) continue;
    std::memcpy(g_live_paths[i], text.c_str(), text.size() + 1);
    g_live[i].store(kLive, std::memory_order_release);
    return i;
  }
  return kLiveFiles;
}

void release_for_signals(std::size_t slot) {
  if (slot < kLiveFiles) g_live[slot].store(kFree, std::memory_order_release);
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
  install_handler_once();
  // A new file under a name no one can guess: the process and a random part. O_EXCL refuses a
  // name that exists (a planted file or symlink, or another run's), O_NOFOLLOW a symlink, and
  // another name is tried.
  static thread_local std::mt19937_64 random{std::random_device{}()};
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temporary_ = path_;
    temporary_ += fmt::format(".partial-{}-{:012x}", static_cast<long>(::getpid()),
                              random() & 0xffffffffffffULL);
    fd = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd >= 0) file_ = ::fdopen(fd, "wb");
  if (file_ == nullptr) {
    const int error = errno;
    if (fd >= 0) {
      ::close(fd);
      ::unlink(temporary_.c_str());
    }
    throw std::runtime_error(
        fmt::format("cannot write {}: {}", path_.string(), std::generic_category().message(error)));
  }
  signal_slot_ = hold_for_signals(temporary_);
}

AtomicFile::~AtomicFile() {
  if (file_ != nullptr) std::fclose(file_);
  if (!renamed_) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
  release_for_signals(signal_slot_);
}

void AtomicFile::finish() {
  const bool write_failed = std::ferror(file_) != 0;
  const bool close_failed = std::fclose(file_) != 0;
  file_ = nullptr;
  if (write_failed || close_failed) {
    throw std::runtime_error(fmt::format("error writing {}", path_.string()));
  }
  if (renamed_) return;  // published: it is in place already
  std::error_code error;
  std::filesystem::rename(temporary_, path_, error);
  if (error) {
    throw std::runtime_error(fmt::format("cannot write {}: {}", path_.string(), error.message()));
  }
  renamed_ = true;
  release_for_signals(signal_slot_);  // a stop from here finds no temporary file to remove
  signal_slot_ = kLiveFiles;
}

void AtomicFile::flush() {
  if (std::fflush(file_) != 0 || std::ferror(file_) != 0) {
    throw std::runtime_error(fmt::format("error writing {}", path_.string()));
  }
}

void AtomicFile::publish() {
  flush();
  std::error_code error;
  std::filesystem::rename(temporary_, path_, error);
  if (error) {
    throw std::runtime_error(fmt::format("cannot write {}: {}", path_.string(), error.message()));
  }
  renamed_ = true;
  release_for_signals(signal_slot_);  // a stop from here leaves the rows so far in place
  signal_slot_ = kLiveFiles;
}

void install_copy(const std::filesystem::path& made, const std::filesystem::path& destination) {
  std::FILE* in = std::fopen(made.c_str(), "rb");
  if (in == nullptr) {
    throw std::runtime_error(
        fmt::format("cannot read {}: {}", made.string(), std::generic_category().message(errno)));
  }
  AtomicFile out(destination);
  std::array<char, 1 << 16> chunk;
  std::size_t got = 0;
  while ((got = std::fread(chunk.data(), 1, chunk.size(), in)) > 0) {
    out.write(std::string_view(chunk.data(), got));
  }
  const bool read_failed = std::ferror(in) != 0;
  std::fclose(in);
  if (read_failed) throw std::runtime_error(fmt::format("error reading {}", made.string()));
  out.finish();
}

}  // namespace tumble
