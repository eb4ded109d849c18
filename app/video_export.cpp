#include "video_export.hpp"

#include <unistd.h>

#include <fmt/core.h>
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string_view>
#include <system_error>
#include <vector>

#include "child_process.hpp"
#include "tumble/output/atomic_file.hpp"

namespace tumble::cli {
namespace {

namespace fs = std::filesystem;

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

}  // namespace

VideoRequest parse_video_request(const RunArguments& args) {
  VideoRequest video;
  video.path = args.video;
  const std::string extension = lowercase_extension(video.path);
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
  const fs::path destination = fs::absolute(video.path, error);
  if (!error) fs::create_directories(destination.parent_path(), error);
  if (error) throw VideoError(fmt::format("cannot write it: {}", error.message()));
  // The renderer writes into a directory of tumble's own; the finished video is then installed
  // through an AtomicFile, so nothing planted beside the destination is ever written through.
  std::optional<TemporaryDirectory> scratch;
  try {
    scratch.emplace("tumble-video");
  } catch (const std::runtime_error& e) {
    throw VideoError(e.what());
  }
  const fs::path output = scratch->path() / ("video" + lowercase_extension(video.path));

  const std::string node = getenv_or("TUMBLE_NODE", "node");
  ChildOutcome result;
  try {
    result = run_child(
        {
            node,
            TUMBLE_VIDEO_SCRIPT,
            fs::absolute(page).string(),
            output.string(),
            std::to_string(video.width),
            std::to_string(video.height),
            std::to_string(video.fps),
            fmt::format("{}", video.speed),  // the shortest text that reads back as the same double
            std::to_string(frames),
            getenv_or("TUMBLE_CHROMIUM", "/usr/bin/chromium"),
        },
        ChildOutput::Capture);
  } catch (const ChildInterrupted&) {
    throw;  // run_command ends by the signal once the temporary page is gone
  } catch (const ChildProcessError& e) {
    throw VideoError(e.not_found() ? fmt::format("{} not found: install Node.js (scripts/setup.sh) "
                                                 "or set TUMBLE_NODE to the node executable",
                                                 node)
                                   : std::string(e.what()));
  }
  if (!result.succeeded()) {
    const std::string reason = last_line(result.output);
    throw VideoError(reason.empty()
                         ? fmt::format("{} failed ({})", TUMBLE_VIDEO_SCRIPT, result.how_it_ended())
                         : reason);
  }
  if (fs::file_size(output, error) == 0 || error) {
    throw VideoError("the renderer reported success but wrote nothing");
  }
  try {
    install_copy(output, destination);
  } catch (const std::runtime_error& e) {
    throw VideoError(e.what());
  }
}

}  // namespace tumble::cli
