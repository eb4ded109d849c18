// Loaders for the two mesh formats a scenario may name: Wavefront .obj and STL (ASCII or binary).
#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string_view>

#include "tumble/inertia/mesh.hpp"
#include "tumble/input/bounded_read.hpp"

namespace tumble {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw MeshError("mesh file '" + path + "': " + what);
}

[[noreturn]] void fail_at_line(const std::string& path, int line, const std::string& what) {
  fail(path, "line " + std::to_string(line) + ": " + what);
}

std::string read_whole_file(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    fail(path, std::filesystem::exists(path, error) ? "is not a regular file"
                                                    : "cannot be read: no such file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be opened for reading");
  try {
    return read_bounded(path, in, kMeshReadLimit);
  } catch (const ReadLimitError& e) {
    fail(path, e.what());
  } catch (const std::runtime_error&) {
    fail(path, "read error");
  }
}

std::string lower_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

bool parse_double(std::string_view token, double& value) {
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end && std::isfinite(value);
}

std::vector<std::string_view> split_whitespace(std::string_view text) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    const std::size_t start = i;
    while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i > start) tokens.push_back(text.substr(start, i - start));
  }
  return tokens;
}

// ---- Wavefront OBJ ----------------------------------------------------------------------------
// "v x y z [w]" adds a vertex; "f a b c ..." a polygon whose corners are "v", "v/vt", "v/vt/vn"
// or "v//vn", with 1-based indices, or negative ones counting back from the latest vertex.
// Every other record (vt, vn, g, o, s, usemtl, mtllib, l, ...) carries nothing about the solid.
TriangleMesh load_obj(const std::string& path, const std::string& text) {
  TriangleMesh mesh;
  std::istringstream lines(text);
  std::string line;
  int line_number = 0;
  while (std::getline(lines, line)) {
    ++line_number;
    std::string_view content(line);
    if (const auto hash = content.find('#'); hash != std::string_view::npos) {
      content = content.substr(0, hash);
    }
    const std::vector<std::string_view> tokens = split_whitespace(content);
    if (tokens.empty()) continue;

    if (tokens[0] == "v") {
      Vec3 p;
      if (tokens.size() < 4 || !parse_double(tokens[1], p.x()) || !parse_double(tokens[2], p.y()) ||
          !parse_double(tokens[3], p.z())) {
        fail_at_line(path, line_number, "a vertex needs three finite coordinates: '" + line + "'");
      }
      mesh.vertices.push_back(p);
    } else if (tokens[0] == "f") {
      if (tokens.size() < 4) {
        fail_at_line(path, line_number, "a face needs at least 3 vertices: '" + line + "'");
      }
      std::vector<int> corners;
      const int defined = static_cast<int>(mesh.vertices.size());
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        const std::string_view index_text = tokens[k].substr(0, tokens[k].find('/'));
        int index = 0;
        const char* end = index_text.data() + index_text.size();
        const auto [ptr, ec] = std::from_chars(index_text.data(), end, index);
        if (ec != std::errc() || ptr != end || index == 0) {
          fail_at_line(path, line_number,
                       "cannot read vertex index '" + std::string(tokens[k]) + "' of a face");
        }
        const int zero_based = index > 0 ? index - 1 : defined + index;
        if (zero_based < 0 || zero_based >= defined) {
          fail_at_line(path, line_number,
                       "face refers to vertex " + std::to_string(index) + " but only " +
                           std::to_string(defined) + " vertices are defined before it");
        }
        corners.push_back(zero_based);
      }
      // A planar convex polygon as a fan of triangles from its first corner; the fan keeps the
      // polygon's winding.
      for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
        mesh.triangles.push_back({corners[0], corners[k], corners[k + 1]});
      }
    }
  }
  if (mesh.triangles.empty()) fail(path, "contains no faces ('f' records)");
  return mesh;
}

// ---- STL --------------------------------------------------------------------------------------
// STL stores every triangle with its own three corners; equal corners are merged into one vertex
// so that neighbouring triangles share their edges (exact equality: a well-formed STL writes a
// shared corner with the same numbers each time).
class VertexMerger {
 public:
  explicit VertexMerger(TriangleMesh& mesh) : mesh_(mesh) {}
  int index_of(const Vec3& p) {
    const auto [it, inserted] =
        index_.try_emplace({p.x(), p.y(), p.z()}, static_cast<int>(mesh_.vertices.size()));
    if (inserted) mesh_.vertices.push_back(p);
    return it->second;
  }

 private:
  TriangleMesh& mesh_;
  std::map<std::array<double, 3>, int> index_;
};

// Binary STL: 80-byte header, uint32 triangle count, then per triangle 12 little-endian float32
// (normal, three corners) and a uint16 attribute: 84 + 50 n bytes in all.
constexpr std::size_t kStlHeaderBytes = 84;
constexpr std::size_t kStlTriangleBytes = 50;

std::uint32_t read_u32_le(const std::string& bytes, std::size_t offset) {
  std::uint32_t value = 0;
  for (int k = 3; k >= 0; --k) {
    value = (value << 8) | static_cast<unsigned char>(bytes[offset + static_cast<std::size_t>(k)]);
  }
  return value;
}

bool is_binary_stl(const std::string& bytes) {
  // Some binary exporters begin the header with "solid" too, so the size decides.
  if (bytes.size() < kStlHeaderBytes) return false;
  const std::uint64_t count = read_u32_le(bytes, 80);
  return bytes.size() == kStlHeaderBytes + kStlTriangleBytes * count;
}

TriangleMesh load_binary_stl(const std::string& path, const std::string& bytes) {
  TriangleMesh mesh;
  VertexMerger merger(mesh);
  const std::size_t count = read_u32_le(bytes, 80);
  for (std::size_t t = 0; t < count; ++t) {
    const std::size_t record = kStlHeaderBytes + kStlTriangleBytes * t;
    std::array<int, 3> triangle{};
    for (std::size_t corner = 0; corner < 3; ++corner) {
      Vec3 p;
      for (std::size_t axis = 0; axis < 3; ++axis) {
        const std::size_t offset = record + 12 + 12 * corner + 4 * axis;  // skip the normal
        p(static_cast<Eigen::Index>(axis)) =
            static_cast<double>(std::bit_cast<float>(read_u32_le(bytes, offset)));
      }
      if (!p.allFinite()) {
        fail(path, "triangle " + std::to_string(t) + " has a non-finite coordinate");
      }
      triangle[corner] = merger.index_of(p);
    }
    mesh.triangles.push_back(triangle);
  }
  if (mesh.triangles.empty()) fail(path, "binary STL with no triangles");
  return mesh;
}

// ASCII STL: solid NAME { facet normal nx ny nz  outer loop  vertex x y z (x3)  endloop
// endfacet } endsolid NAME. Only the vertices matter; the winding gives the outward normal.
TriangleMesh load_ascii_stl(const std::string& path, const std::string& text) {
  TriangleMesh mesh;
  VertexMerger merger(mesh);
  const std::vector<std::string_view> tokens = split_whitespace(text);
  if (tokens.empty() || tokens[0] != "solid") {
    fail(path, "neither an ASCII STL (which starts with 'solid') nor a binary STL (whose size is " +
                   std::to_string(kStlHeaderBytes) + " + 50 x the triangle count in bytes 80-83)");
  }
  std::vector<int> corners;
  int facet = 0;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (tokens[i] == "facet") {
      corners.clear();
    } else if (tokens[i] == "vertex") {
      Vec3 p;
      if (i + 3 >= tokens.size() || !parse_double(tokens[i + 1], p.x()) ||
          !parse_double(tokens[i + 2], p.y()) || !parse_double(tokens[i + 3], p.z())) {
        fail(path, "facet " + std::to_string(facet) + ": a vertex needs three finite coordinates");
      }
      corners.push_back(merger.index_of(p));
      i += 3;
    } else if (tokens[i] == "endfacet") {
      if (corners.size() != 3) {
        fail(path, "facet " + std::to_string(facet) + " has " + std::to_string(corners.size()) +
                       " vertices; STL facets are triangles");
      }
      mesh.triangles.push_back({corners[0], corners[1], corners[2]});
      ++facet;
    }
  }
  if (mesh.triangles.empty()) {
    std::string what = "ASCII STL with no facets";
    if (text.size() >= kStlHeaderBytes) {
      what += " (or a binary STL whose size, " + std::to_string(text.size()) +
              " bytes, is not the 84 + 50 x " + std::to_string(read_u32_le(text, 80)) +
              " its header announces: truncated?)";
    }
    fail(path, what);
  }
  return mesh;
}

}  // namespace

TriangleMesh load_mesh(const std::string& path) {
  const std::string extension = lower_extension(path);
  if (extension != ".obj" && extension != ".stl") {
    fail(path, "unknown extension '" + extension + "' (expected .obj or .stl)");
  }
  const std::string bytes = read_whole_file(path);
  if (extension == ".obj") return load_obj(path, bytes);
  return is_binary_stl(bytes) ? load_binary_stl(path, bytes) : load_ascii_stl(path, bytes);
}

}  // namespace tumble
