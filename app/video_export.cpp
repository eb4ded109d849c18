#include "video_export.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/core.h>
#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <string_view>
#include <system_error>
#include <vector>

extern char** environ;

namespace tumble::cli {
namespace {

namespace fs = std::filesystem;

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// One side of WIDTHxHEIGHT: digits only, 16 to 8192 pixels.
int parse_side(std::string_view text, std::string_view size) {
  constexpr int kMin = 16;
  constexpr int kMax = 8192;
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || value < kMin ||
      value > kMax) {
    throw std::invalid_argument(fmt::format(
        "--video-size {}: expected WIDTHxHEIGHT in pixels, each {} to {}", size, kMin, kMax));
  }
  return value;
}

std::string getenv_or(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? value : fallback;
}

// The last line the script wrote, without its "render_video: " prefix: its one-line reason.
std::string last_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  const std::size_t newline = text.rfind('\n');
  std::string line = newline == std::string::npos ? text : text.substr(newline + 1);
  constexpr std::string_view kPrefix = "render_video: ";
  if (line.starts_with(kPrefix)) line.erase(0, kPrefix.size());
  return line;
}

// While the renderer runs, SIGINT, SIGTERM and SIGHUP are passed on to it instead of ending
// tumble at once: the script then removes its partial video, and tumble, returning normally,
// removes the temporary page. (Ctrl-C reaches both anyway; a signal sent to tumble alone would
// otherwise leave the renderer running.)
volatile std::sig_atomic_t g_renderer_pid = 0;
volatile std::sig_atomic_t g_signal = 0;

extern "C" void forward_signal(int signal_number) {
  g_signal = signal_number;
  if (g_renderer_pid > 0) ::kill(static_cast<pid_t>(g_renderer_pid), signal_number);
}

class ForwardSignals {
 public:
  ForwardSignals() {
    g_signal = 0;
    g_renderer_pid = 0;
    struct sigaction action {};
    action.sa_handler = forward_signal;
    sigemptyset(&action.sa_mask);
    for (std::size_t i = 0; i < kSignals.size(); ++i) {
      ::sigaction(kSignals[i], &action, &previous_[i]);
    }
  }
  ForwardSignals(const ForwardSignals&) = delete;
  ForwardSignals& operator=(const ForwardSignals&) = delete;
  ~ForwardSignals() {
    g_renderer_pid = 0;
    for (std::size_t i = 0; i < kSignals.size(); ++i) {
      ::sigaction(kSignals[i], &previous_[i], nullptr);
    }
  }
  // Started: a signal that came before the pid was known is passed on now.
  void started(pid_t pid) {
    g_renderer_pid = pid;
    if (g_signal != 0) ::kill(pid, g_signal);
  }
  int received() const { return g_signal; }

 private:
  static constexpr std::array<int, 3> kSignals = {SIGINT, SIGTERM, SIGHUP};
  std::array<struct sigaction, 3> previous_{};
};

struct ScriptResult {
  int wait_status = 0;
  std::string output;  // the script's stdout and stderr together, its last 8 KB
};

// Runs argv[0] (searched on PATH) with stdin from /dev/null and stdout and stderr into a pipe
// that is read here: the script's messages become tumble's one-line reason, and nothing it
// prints can mix into the summary on stdout.
ScriptResult run_capturing(std::vector<std::string> args) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::array<int, 2> pipe_fds{};
  if (::pipe2(pipe_fds.data(), O_CLOEXEC) != 0) {
    throw VideoError("cannot make a pipe: " + std::generic_category().message(errno));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  ForwardSignals forward;
  pid_t pid = 0;
  const int spawn_error = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fds[1]);
  if (spawn_error != 0) {
    ::close(pipe_fds[0]);
    throw VideoError(spawn_error == ENOENT
                         ? fmt::format("{} not found: install Node.js (scripts/setup.sh) or set "
                                       "TUMBLE_NODE to the node executable",
                                       args[0])
                         : fmt::format("cannot run {}: {}", args[0],
                                       std::generic_category().message(spawn_error)));
  }
  forward.started(pid);
  ScriptResult result;
  std::array<char, 4096> buffer{};
  for (;;) {
    const ssize_t n = ::read(pipe_fds[0], buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    result.output.append(buffer.data(), static_cast<std::size_t>(n));
    constexpr std::size_t kKeep = 8192;
    if (result.output.size() > 2 * kKeep) result.output.erase(0, result.output.size() - kKeep);
  }
  ::close(pipe_fds[0]);
  while (::waitpid(pid, &result.wait_status, 0) < 0) {
    if (errno != EINTR) {
      throw VideoError("waiting for the renderer: " + std::generic_category().message(errno));
    }
  }
  if (forward.received() != 0) {
    throw VideoError(fmt::format("interrupted ({})", ::strsignal(forward.received())));
  }
  return result;
}

}  // namespace

TemporaryDirectory::TemporaryDirectory() {
  std::error_code error;
  std::string name = (fs::temp_directory_path(error) / "tumble-video-XXXXXX").string();
  if (error || ::mkdtemp(name.data()) == nullptr) {
    throw VideoError(fmt::format("cannot make a temporary directory for the page: {}",
                                 error ? error.message() : std::generic_category().message(errno)));
  }
  path_ = name;
}

TemporaryDirectory::~TemporaryDirectory() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

VideoRequest parse_video_request(const RunArguments& args) {
  VideoRequest video;
  video.path = args.video;
  const std::string extension = lowercase(video.path.extension().string());
  if (extension != ".mp4" && extension != ".gif") {
    throw std::invalid_argument(
        fmt::format("--video {}: the video's name must end in .mp4 or .gif", args.video));
  }
  video.format = extension == ".gif" ? VideoFormat::Gif : VideoFormat::Mp4;
  const std::string_view size = args.video_size;
  const std::size_t x = size.find_first_of("xX");
  if (x == std::string_view::npos) {
    throw std::invalid_argument(
        fmt::format("--video-size {}: expected WIDTHxHEIGHT in pixels, e.g. 1280x720", size));
  }
  video.width = parse_side(size.substr(0, x), size);
  video.height = parse_side(size.substr(x + 1), size);
  // H.264 in yuv420p, the only pixel format every player takes, stores colour at half
  // resolution in both directions: libx264 refuses odd sides.
  if (video.format == VideoFormat::Mp4 && (video.width % 2 != 0 || video.height % 2 != 0)) {
    throw std::invalid_argument(
        fmt::format("--video-size {}: an .mp4 needs an even width and height (e.g. {}x{})", size,
                    video.width + video.width % 2, video.height + video.height % 2));
  }
  video.fps = args.video_fps;
  video.speed = args.video_speed;
  if (!(video.speed > 0.0) || !std::isfinite(video.speed)) {
    throw std::invalid_argument(
        fmt::format("--video-speed {}: expected a positive number of simulation seconds per second",
                    args.video_speed));
  }
  return video;
}

long video_frame_count(double t0, double t_end, const VideoRequest& video) {
  // Frame steps in the span; the slack of a billionth of a step keeps the last row when the span
  // is a whole number of steps but for rounding (20 s at 2x and 10 fps: 100 steps, 101 frames).
  const double steps = std::max(0.0, t_end - t0) * video.fps / video.speed;
  if (!(steps < static_cast<double>(kMaxVideoFrames))) {
    throw std::invalid_argument(fmt::format(
        "--video: t = {:g} to {:g} s at {} fps and speed {:g} would take more than {} frames: "
        "raise --video-speed or lower --video-fps",
        t0, t_end, video.fps, video.speed, kMaxVideoFrames));
  }
  const long frames = static_cast<long>(std::floor(steps + 1e-9)) + 1;
  const double pixels = static_cast<double>(frames) * video.width * video.height;
  if (video.format == VideoFormat::Gif && pixels > kMaxGifPixels) {
    throw std::invalid_argument(fmt::format(
        "--video {}: {} frames of {}x{} are too many for a GIF (ffmpeg would hold about {:.1f} GB "
        "to make its palette): lower --video-size or --video-fps, raise --video-speed, or make "
        "an .mp4",
        video.path.string(), frames, video.width, video.height, 4.2e-9 * pixels));
  }
  return frames;
}

void render_video(const fs::path& page, const VideoRequest& video, long frames) {
  std::error_code error;
  const fs::path output = fs::absolute(video.path, error);
  if (!error) fs::create_directories(output.parent_path(), error);
  if (error) throw VideoError(fmt::format("cannot write it: {}", error.message()));

  const ScriptResult result = run_capturing({
      getenv_or("TUMBLE_NODE", "node"),
      TUMBLE_VIDEO_SCRIPT,
      fs::absolute(page).string(),
      output.string(),
      std::to_string(video.width),
      std::to_string(video.height),
      std::to_string(video.fps),
      fmt::format("{}", video.speed),  // the shortest text that reads back as the same double
      std::to_string(frames),
      getenv_or("TUMBLE_CHROMIUM", "/usr/bin/chromium"),
  });
  const int status = result.wait_status;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const std::string reason = last_line(result.output);
    throw VideoError(reason.empty()
                         ? fmt::format("{} failed ({} {})", TUMBLE_VIDEO_SCRIPT,
                                       WIFEXITED(status) ? "exit status" : "signal",
                                       WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status))
                         : reason);
  }
  if (fs::file_size(output, error) == 0 || error) {
    throw VideoError("the renderer reported success but wrote nothing");
  }
}

}  // namespace tumble::cli
