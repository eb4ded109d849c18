#pragma once
// `tumble run --video`: a video of the animation page's 3D view (docs/video.md). The page is the
// only renderer: web/render_video.mjs opens it in headless Chromium, screenshots one frame per
// time step and pipes the frames to ffmpeg. This file checks the options, counts the frames and
// runs the script.
#include <filesystem>
#include <stdexcept>
#include <string>

#include "commands.hpp"

namespace tumble::cli {

enum class VideoFormat { Mp4, Gif };

struct VideoRequest {
  std::filesystem::path path;  // .mp4 or .gif
  VideoFormat format = VideoFormat::Mp4;
  int width = 1280;    // pixels
  int height = 720;    // pixels
  int fps = 30;        // frames per second of video
  double speed = 1.0;  // simulation seconds per second of video
};

// The --video options, checked: the extension, WxH (even for .mp4), a positive finite speed.
// Throws std::invalid_argument with the message for the user (a bad command line).
VideoRequest parse_video_request(const RunArguments& args);

// The number of frames for rows from t0 to t_end (docs/video.md): frame k shows
// t0 + k * speed / fps, for every k whose time is at most t_end, so the first frame shows the
// first row, the last the last row when the span is a whole number of frame steps, and the video
// lasts exactly frames / fps. Throws std::invalid_argument past kMaxVideoFrames, or for a GIF
// past kMaxGifPixels.
long video_frame_count(double t0, double t_end, const VideoRequest& video);
inline constexpr long kMaxVideoFrames = 100'000;
// A GIF's one palette is made from every frame before the first is written, so ffmpeg holds all
// of them decoded, about 4 bytes a pixel: frames x width x height up to this, about 1 GB.
inline constexpr double kMaxGifPixels = 268'435'456.0;  // 2^28

// Why no video was written; the file was left untouched.
class VideoError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Renders `page` into video.path with web/render_video.mjs, run by node without a shell.
// Throws VideoError naming the cause (node, Chromium or ffmpeg missing, or the page failing).
void render_video(const std::filesystem::path& page, const VideoRequest& video, long frames);

}  // namespace tumble::cli
