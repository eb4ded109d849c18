#include "tumble/simulation/checkpoint_file.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <fstream>
#include <iterator>
#include <system_error>

#include "tumble/input/bounded_read.hpp"
#include "tumble/output/atomic_file.hpp"
#include "tumble/simulation/checkpoint_fields.hpp"
#include "tumble/simulation/text_archive.hpp"

namespace tumble {

namespace {

constexpr long kFormat = 3;
constexpr std::string_view kDigestKey = "digest ";

std::string hex(std::uint64_t value) {
  return fmt::format("{:016x}", value);
}

// A 64-bit field written in hex (a digest does not fit a long's decimal range).
void archive_hex(StateArchive& archive, std::string_view key, std::uint64_t& value) {
  std::string text = hex(value);
  archive.text(key, text);
  if (archive.loading()) {
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value, 16);
    if (ec != std::errc() || ptr != end || text.empty()) {
      archive.fail(key, fmt::format("'{}' is not a hexadecimal number", text));
    }
  }
}

// The file's head: what it is, and where it came from. One list of fields for both ways.
void archive_origin(StateArchive& archive, CheckpointOrigin& origin, std::string& integrator) {
  long format = kFormat;
  archive.integer("format", format);
  if (format != kFormat) {
    archive.fail("format",
                 fmt::format("format {} is not one this tumble reads ({})", format, kFormat));
  }
  archive.text("scenario", origin.scenario);
  archive_hex(archive, "fingerprint", origin.fingerprint);
  archive.integer("trajectory_rows", origin.trajectory_rows);
  long bytes = static_cast<long>(origin.trajectory_bytes);
  archive.integer("trajectory_bytes", bytes);
  if (bytes < 0) archive.fail("trajectory_bytes", "a count of bytes is not negative");
  origin.trajectory_bytes = static_cast<std::uint64_t>(bytes);
  archive_hex(archive, "trajectory_digest", origin.trajectory_digest);
  archive.text("integrator", integrator);
}

// The file's text, read no further than its limit (a checkpoint named /dev/zero would otherwise
// be read until memory runs out).
std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointFileError(fmt::format("{}:0: cannot be read", path.string()));
  try {
    return read_bounded(path.string(), in, kCheckpointReadLimit);
  } catch (const ReadLimitError& e) {
    throw CheckpointFileError(fmt::format("{}:0: {}", path.string(), e.what()));
  } catch (const std::runtime_error&) {
    throw CheckpointFileError(fmt::format("{}:0: cannot be read", path.string()));
  }
}

// The text before the last line, "digest HEX" of that text; throws if it is not there or does
// not match (a file cut short, or changed after it was written).
std::string_view verified_body(const std::string& text, const std::string& file) {
  const std::string_view all(text);
  const std::size_t last_start =
      all.size() >= 2 ? all.rfind('\n', all.size() - 2) : std::string_view::npos;
  const std::string_view body =
      last_start == std::string_view::npos ? std::string_view() : all.substr(0, last_start + 1);
  const std::string_view last =
      last_start == std::string_view::npos ? all : all.substr(last_start + 1);
  if (body.empty() || !last.starts_with(kDigestKey) || !last.ends_with('\n') ||
      hex(content_digest(body)) != last.substr(kDigestKey.size(), 16) ||
      last.size() != kDigestKey.size() + 17) {
    throw CheckpointFileError(fmt::format(
        "{}:0: not a whole tumble checkpoint: its last line is not the digest of the lines "
        "before it (the file was cut short or changed after it was written)",
        file));
  }
  return body;
}

}  // namespace

std::uint64_t content_digest(std::string_view bytes, std::uint64_t digest) {
  for (const char c : bytes) {
    digest ^= static_cast<unsigned char>(c);
    digest *= 1099511628211u;
  }
  return digest;
}

std::uint64_t file_digest(const std::filesystem::path& path, std::uint64_t* bytes) {
  // A device or a FIFO may have no end (a trajectory linked to /dev/zero): only files are read.
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw std::runtime_error(fmt::format("{}: is not a regular file", path.string()));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot be read", path.string()));
  std::uint64_t digest = content_digest({});
  std::uint64_t count = 0;
  char buffer[1 << 16];
  while (in) {
    in.read(buffer, sizeof buffer);
    const auto got = static_cast<std::size_t>(in.gcount());
    digest = content_digest({buffer, got}, digest);
    count += got;
  }
  if (in.bad()) throw std::runtime_error(fmt::format("{}: cannot be read", path.string()));
  if (bytes != nullptr) *bytes = count;
  return digest;
}

std::uint64_t scenario_fingerprint(std::string_view scenario_text,
                                   const std::vector<ParameterOverride>& overrides) {
  std::uint64_t digest = content_digest(scenario_text);
  for (const ParameterOverride& o : overrides) {
    digest = content_digest(std::string_view("\n--set ", 7), digest);
    digest = content_digest(o.name, digest);
    digest = content_digest("=", digest);
    digest = content_digest(o.value, digest);
  }
  return digest;
}

void write_checkpoint_file(const std::filesystem::path& path,
                           const SimulationCheckpoint& checkpoint, const CheckpointOrigin& origin) {
  TextArchiveWriter out;
  out.comment(fmt::format(
      "tumble checkpoint: a run of {} stopped at t = {} s. `tumble run {} --resume FILE` (with "
      "the same --set values) goes on from here, as if it had never stopped.",
      origin.scenario, checkpoint.t(), origin.scenario));
  out.comment(
      "One field a line; every number reads back exactly. The last line is the digest "
      "of the lines before it: an edited file is refused.");
  CheckpointOrigin head = origin;
  std::string integrator(checkpoint.driver.integrator->name());
  archive_origin(out, head, integrator);
  out.enter("integrator");
  // A writing archive only reads the fields it is handed: the shared method is not changed.
  const_cast<Integrator&>(*checkpoint.driver.integrator).archive_memory(out);
  out.leave();
  SimulationCheckpoint fields = checkpoint;
  archive_checkpoint_fields(out, fields);

  const std::string& body = out.written();
  AtomicFile file(path);
  file.write(body);
  file.write(fmt::format("{}{}\n", kDigestKey, hex(content_digest(body))));
  file.finish();
}

LoadedCheckpoint read_checkpoint_file(const std::filesystem::path& path,
                                      PreparedSimulation& simulation) {
  return read_checkpoint_text(read_text(path), path.string(), simulation);
}

LoadedCheckpoint read_checkpoint_text(const std::string& text, const std::string& file,
                                      PreparedSimulation& simulation) {
  TextArchiveReader in(verified_body(text, file), file);
  LoadedCheckpoint loaded;
  std::string integrator_name;
  archive_origin(in, loaded.origin, integrator_name);
  if (integrator_name != simulation.integrator->name()) {
    in.fail("integrator", fmt::format("the checkpoint is of a run by {}; this run's method is {}",
                                      integrator_name, simulation.integrator->name()));
  }

  // The method as start() makes it for this run (its workspace, its system), then its memory.
  OdeSystem& system = ode_system_of(simulation);
  system.begin(simulation.t0, simulation.y0);
  std::unique_ptr<Integrator> integrator = simulation.integrator->clone_onto(system);
  integrator->start(system, simulation.t0, simulation.y0, simulation.t_end);
  SimulationCheckpoint& checkpoint = loaded.checkpoint;
  try {
    in.enter("integrator");
    integrator->archive_memory(in);
    in.leave();
    checkpoint.driver.integrator = std::move(integrator);
    archive_checkpoint_fields(in, checkpoint);
  } catch (const std::invalid_argument& e) {
    in.fail("", e.what());
  }
  if (!in.at_end()) in.fail("", "more fields than a checkpoint has");

  // What the rest of the run indexes by must fit this model.
  const std::size_t event_count = system.events().size();
  const DriverPosition& position = checkpoint.driver.position;
  const std::size_t contact_count = simulation.formulation->hybrid_state().contact.contacts.size();
  bool fits = static_cast<std::size_t>(position.g_before.size()) == event_count &&
              checkpoint.hybrid.contact.contacts.size() == contact_count;
  for (const EventRecord& e : position.events) fits = fits && e.index < event_count;
  for (const ContactEventRecord& e : checkpoint.hybrid.contact.events) {
    fits = fits && e.contact < contact_count;
  }
  // A contact's feature names vertices of its surface: the model's, no other and no more (the
  // feature's room was made for them before the run, so that a step allocates nothing).
  const std::vector<PlaneContact>& contacts = simulation.formulation->model().contacts;
  for (std::size_t c = 0; fits && c < contact_count && c < contacts.size(); ++c) {
    const auto vertices = static_cast<int>(contacts[c].surface.vertices.size());
    const ContactFeature& feature = checkpoint.hybrid.contact.contacts[c].feature;
    const auto names_a_vertex = [vertices](int v) { return v >= 0 && v < vertices; };
    fits = feature.size() <= vertices && static_cast<int>(feature.inward_B.size()) <= vertices &&
           std::all_of(feature.polygon.begin(), feature.polygon.end(), names_a_vertex) &&
           std::all_of(feature.normal_points.begin(),
                       feature.normal_points.begin() + feature.normal_point_count, names_a_vertex);
  }
  if (!fits) {
    throw CheckpointFileError(fmt::format(
        "{}:0: the checkpoint's events and contacts are not this scenario's ({} events, {} "
        "contacts): it is of another scenario",
        file, event_count, contact_count));
  }
  return loaded;
}

}  // namespace tumble
