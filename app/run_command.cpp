#include <fmt/core.h>
#include <algorithm>
#include <filesystem>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "child_process.hpp"
#include "commands.hpp"
#include "exit_status.hpp"
#include "output_files.hpp"
#include "system_summary.hpp"
#include "tumble/integrators/auto_switching.hpp"
#include "tumble/output/animation_html.hpp"
#include "tumble/output/events_csv.hpp"
#include "tumble/output/trajectory_csv.hpp"
#include "tumble/scenario/scenario_document.hpp"
#include "tumble/simulation/checkpoint_file.hpp"
#include "tumble/simulation/simulation.hpp"
#include "video_export.hpp"

namespace tumble::cli {

std::vector<ParameterOverride> parse_overrides(const std::vector<std::string>& sets) {
  std::vector<ParameterOverride> overrides;
  for (const std::string& set : sets) {
    const auto eq = set.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == set.size()) {
      throw std::invalid_argument("--set " + set + ": expected NAME=VALUE");
    }
    overrides.push_back({set.substr(0, eq), set.substr(eq + 1)});
  }
  return overrides;
}

std::optional<Scenario> load_scenario_for(const char* command, const std::string& path,
                                          const std::vector<std::string>& sets, int& status) {
  try {
    return load_scenario(path, parse_overrides(sets));
  } catch (const ScenarioError& e) {
    fmt::print(stderr, "{}\n", e.what());
    status = kInvalidScenario;
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "tumble {}: {}\n", command, e.what());
    status = kBadCommandLine;
  }
  return std::nullopt;
}

namespace {

// The joints that close loops (and the rods, held the same way), and how far their rows were
// from closing at worst.
void print_loop_closure(const Scenario& scenario, const LoopErrors& worst) {
  std::string joints;
  for (const JointSpec& joint : scenario.joints) {
    if (!joint.closes_loop) continue;
    if (!joints.empty()) joints += ", ";
    joints += joint.name;
    if (joint.type == JointType::Distance) joints += " (a rod)";
  }
  if (joints.empty()) return;
  fmt::print(
      "  loops          closed by {}: held to {:.3e} m and {:.3e} rad, their velocity rows to "
      "{:.3e} (m/s, rad/s); reactions least-norm where rows repeat\n",
      joints, worst.gap, worst.turn, worst.speed);
}

// `auto`'s methods: which took how many steps, and each switch with the test that decided it.
void print_method_switches(const Integrator& integrator) {
  const auto* automatic = dynamic_cast<const AutoSwitching*>(&integrator);
  if (automatic == nullptr) return;
  fmt::print("  methods        dop853 {} steps, radau5 {} steps", automatic->explicit_steps(),
             automatic->implicit_steps());
  if (automatic->switch_count() == 0) {
    if (automatic->stiff_without_jacobian_at() >= 0.0) {
      fmt::print(
          "; stiff from t = {:.6g} s (dop853's steps held by its stability), but radau5 needs the "
          "equations' Jacobian, which this run's form does not give (free bodies under gravity "
          "alone, in their body-frame form): dop853 went on\n",
          automatic->stiff_without_jacobian_at());
    } else {
      fmt::print(" (no stiffness: dop853 throughout)\n");
    }
    return;
  }
  fmt::print("\n");
  for (const MethodSwitch& change : automatic->switches()) {
    if (change.to_implicit) {
      fmt::print(
          "  switch         to radau5 at t = {:.6g} s: stiff ({} of dop853's steps held by its "
          "stability, |h lambda| > {:g}, or > {:.3g} on a retried step; the last {:.3g})\n",
          change.t, AutoSwitching::kStiffSteps, AutoSwitching::kExplicitStabilityEdge,
          AutoSwitching::kNearEdge, change.h_lambda);
    } else if (change.modes_without_jacobian()) {
      fmt::print(
          "  switch         to dop853 at t = {:.6g} s: the system's modes now give radau5 no "
          "Jacobian\n",
          change.t);
    } else {
      fmt::print(
          "  switch         to dop853 at t = {:.6g} s: no longer stiff ({} of radau5's steps "
          "within dop853's stability, |h lambda| <= {:g}; the last {:.3g})\n",
          change.t, AutoSwitching::kStiffSteps, 0.5 * AutoSwitching::kExplicitStabilityEdge,
          change.h_lambda);
    }
  }
  const long unlisted = automatic->switch_count() - static_cast<long>(automatic->switches().size());
  if (unlisted > 0) fmt::print("  switch         and {} more\n", unlisted);
}

void print_summary(const Scenario& scenario, const PreparedSimulation& simulation,
                   const SimulationResult& result, const std::filesystem::path& trajectory,
                   const std::optional<std::filesystem::path>& events,
                   const std::optional<std::filesystem::path>& animation,
                   const std::optional<std::string>& video, int digits,
                   const std::vector<std::string>& checkpoint_lines) {
  const SimulateSpec& sim = scenario.simulate;
  const IntegratorStats& stats = result.report.stats;
  fmt::print("{} ({})\n", scenario.name, scenario.file);
  for (const std::string& warning : scenario.warnings) fmt::print("  warning        {}\n", warning);
  fmt::print("  integrator     {} (formulation: {})", simulation.integrator->name(),
             simulation.formulation->name());
  if (simulation.integrator->adaptive()) {
    fmt::print(", rtol {:g}, atol {:g}", sim.rtol, sim.atol);
    if (sim.rtol_given && !sim.atol_given) fmt::print(" (atol = rtol x 1e-3: set simulate.atol)");
  } else if (sim.step > 0.0) {
    fmt::print(", step {:g} s", sim.step);
  }
  fmt::print("\n  steps          {} accepted, {} rejected\n", stats.accepted_steps,
             stats.rejected_steps);
  fmt::print("  evaluations    {} of the right-hand side\n", stats.rhs_evaluations);
  print_method_switches(*simulation.integrator);
  fmt::print("  wall time      {:.3f} ms (integration and output)\n", 1e3 * result.wall_seconds);
  const bool forces_act = energy_changes(scenario);
  const ConservationReport& c = result.conservation;
  // A drift is relative to a scale that is not round-off (ConservationReport::energy_scale).
  const std::string energy_drift =
      c.energy_scale() > 0.0
          ? fmt::format(
                "max |E - E0| {:.3e} J, {:.3e} of its scale {:.{}g} J (the larger of |E0| "
                "and the largest KE)",
                c.max_energy_change, c.scaled_energy_drift(), c.energy_scale(), digits)
          : fmt::format("max |E - E0| {:.3e} J (no motion)", c.max_energy_change);
  const std::string momentum_drift =
      c.angular_momentum_scale() > 0.0
          ? fmt::format("max ||L| - |L0|| {:.3e} kg m^2/s, {:.3e} of the largest |L|",
                        c.max_angular_momentum_change, c.scaled_angular_momentum_drift())
          : fmt::format("max |L| {:.3e} kg m^2/s (L = 0 throughout)",
                        c.max_angular_momentum_change);
  // Contacts that only rolled, stuck or slid without friction did no work: their books stay at
  // the level of the integration's own error (the work-energy balance's residual), and E was
  // conserved after all. (Which of those they did is in the events; the books cannot tell.)
  const bool only_contacts = forces_act && only_contacts_may_do_work(scenario);
  const bool contacts_did_no_work =
      only_contacts && c.max_contact_work <= kWorklessFactor * c.max_work_energy_residual;
  fmt::print("  energy E       {}{}\n", energy_drift,
             contacts_did_no_work
                 ? fmt::format(" (the contacts did no work, at most {:.3e} J, within the books' "
                               "own error: rolling, sticking and sliding without friction do "
                               "none, nor do joints: E is conserved)",
                               c.max_contact_work)
             : forces_act ? " (forces, motors, dampers, impulses, locks, friction or impacts do "
                            "work: E is not conserved)"
                          : "");
  fmt::print("  |L| (origin)   {}{}\n", momentum_drift,
             external_moments_act(scenario) ? " (external moments act: |L| is not conserved)" : "");
  fmt::print("  |R^T R - I|    max {:.3e}\n", result.conservation.max_orthonormality_error);
  print_loop_closure(scenario, result.conservation.max_loop_error);
  print_system_summary(scenario, simulation, result, digits);
  print_scenario_events(scenario, result);
  fmt::print("  trajectory     {} ({} rows to t = {:g} s)\n", trajectory.string(), result.rows,
             result.report.t_reached);
  for (const std::string& line : checkpoint_lines) fmt::print("  {}\n", line);
  if (events) {
    fmt::print("  events         {} ({} contact events, {} jumps, {} of the scenario's events)\n",
               events->string(), result.contact_events.size(), result.jumps.size(),
               result.user_events.size());
  }
  if (animation) fmt::print("  animation      {}\n", animation->string());
  if (video) fmt::print("  video          {}\n", *video);
}

// The page's path: output.animation under --out, else with --animate the trajectory's name
// with .html beside it; none when neither asks for it.
std::optional<std::filesystem::path> animation_path(const RunArguments& args,
                                                    const Scenario& scenario,
                                                    const std::filesystem::path& trajectory) {
  if (!scenario.output.animation.empty()) {
    return std::filesystem::path(args.out_dir) / scenario.output.animation;
  }
  if (!args.animate) return std::nullopt;
  std::filesystem::path page = trajectory;
  page.replace_extension(".html");
  return page;
}

// What the page marks on its plots' time axes: the contacts' events, the jumps and the
// scenario's own events, in time order (at one instant: jumps, contacts', the scenario's).
std::vector<AnimationEvent> animation_events(const Scenario& scenario,
                                             const SimulationResult& result) {
  std::vector<std::pair<int, AnimationEvent>> events;
  for (const JumpRecord& jump : result.jumps) events.push_back({0, {jump.t, "jump: " + jump.what}});
  for (const ContactEventRecord& e : result.contact_events) {
    events.push_back({1, {e.t, scenario.contacts[e.contact].name + ": " + e.what}});
  }
  for (const UserEventRecord& e : result.user_events) {
    events.push_back({2, {e.t, "event: " + e.name}});
  }
  std::stable_sort(events.begin(), events.end(), [](const auto& a, const auto& b) {
    return a.second.t != b.second.t ? a.second.t < b.second.t : a.first < b.first;
  });
  std::vector<AnimationEvent> out;
  for (auto& [order, e] : events) out.push_back(std::move(e));
  return out;
}

// Renders the video from the page: the one written for --animate, or else one written for the
// video alone into a temporary directory that goes with it. Returns the summary's line.
std::string make_video(const VideoRequest& video, const std::optional<std::filesystem::path>& page,
                       const Scenario& scenario, const RecordedTrajectory& recorded,
                       std::span<const AnimationEvent> events,
                       const std::filesystem::path& trajectory) {
  const long frames = video_frame_count(recorded.t(0), recorded.t(recorded.rows() - 1), video);
  if (page) {
    render_video(*page, video, frames);
  } else {
    const TemporaryDirectory scratch("tumble-page");
    std::filesystem::path temporary_page = scratch.path() / trajectory.filename();
    temporary_page.replace_extension(".html");
    write_animation_html(temporary_page, make_animation_scene(scenario), recorded, events);
    render_video(temporary_page, video, frames);
  }
  return fmt::format("{} ({} frames, {}x{}, {} fps)", video.path.string(), frames, video.width,
                     video.height, video.fps);
}

// The scenario's identity for a checkpoint: its file's text and the --set values (the file was
// just read: it reads again).
std::uint64_t fingerprint_of(const RunArguments& args) {
  return scenario_fingerprint(read_scenario_file(args.scenario), parse_overrides(args.sets));
}

// The --set options as the command line gave them, each with a space before.
std::string sets_text(const RunArguments& args) {
  std::string text;
  for (const std::string& set : args.sets) text += " --set " + set;
  return text;
}

// A --resume FILE read for this run: its checkpoint, or the message and exit status why not.
std::optional<LoadedCheckpoint> checkpoint_to_resume(const RunArguments& args,
                                                     std::uint64_t fingerprint,
                                                     PreparedSimulation& simulation) {
  std::optional<LoadedCheckpoint> loaded;
  try {
    loaded = read_checkpoint_file(args.resume, simulation);
  } catch (const CheckpointFileError& e) {
    fmt::print(stderr, "tumble run: --resume {}\n", e.what());
    return std::nullopt;
  }
  if (loaded->origin.fingerprint != fingerprint) {
    fmt::print(stderr,
               "tumble run: --resume {}: a checkpoint of {} as it was, with the --set values it "
               "had, when the run stopped; {} {} not that (its text or the --set values differ): "
               "resume with the scenario and --set values the run was stopped with\n",
               args.resume, loaded->origin.scenario, args.scenario,
               args.sets.empty() ? "is" : "with these --set values is");
    return std::nullopt;
  }
  return loaded;
}

// Whether the trajectory at `path` is the one the stopped run wrote (and a resumed run goes on
// with it): true; false where there is none (the resumed run writes the rows after the stop);
// the message and nullopt where it is another file.
std::optional<bool> continues_trajectory(const std::filesystem::path& path,
                                         const CheckpointOrigin& origin,
                                         const std::string& resume) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return false;
  std::uint64_t bytes = 0;
  std::uint64_t digest = 0;
  try {
    // A file of another size is another file: not read (it may be very large).
    if (std::filesystem::is_regular_file(path, error)) bytes = std::filesystem::file_size(path);
    if (bytes == origin.trajectory_bytes) digest = file_digest(path, &bytes);
  } catch (const std::exception& e) {
    fmt::print(stderr, "tumble run: {}\n", e.what());
    return std::nullopt;
  }
  if (bytes != origin.trajectory_bytes || digest != origin.trajectory_digest) {
    fmt::print(stderr,
               "tumble run: --resume {}: {} is not the trajectory the stopped run wrote ({} rows, "
               "{} bytes; this file has {} bytes or other bytes): resume into the stopped run's "
               "--out to go on with its trajectory, or into a directory without one for the rows "
               "after the stop alone\n",
               resume, path.string(), origin.trajectory_rows, origin.trajectory_bytes, bytes);
    return std::nullopt;
  }
  return true;
}

}  // namespace

int run_command(const RunArguments& args) {
  std::optional<VideoRequest> video;
  if (!args.video.empty()) {
    try {
      video = parse_video_request(args);
    } catch (const std::invalid_argument& e) {
      fmt::print(stderr, "tumble run: {}\n", e.what());
      return kBadCommandLine;
    }
  }

  int status = kDone;
  std::optional<Scenario> loaded = load_scenario_for("run", args.scenario, args.sets, status);
  if (!loaded) return status;
  Scenario& scenario = *loaded;

  // The video's frame count is known from the duration: too many is refused now, not after the
  // whole run.
  if (video) {
    try {
      video_frame_count(0.0, scenario.simulate.duration, *video);
    } catch (const std::invalid_argument& e) {
      fmt::print(stderr, "tumble run: {}\n", e.what());
      return kBadCommandLine;
    }
  }

  std::optional<PreparedSimulation> simulation;
  std::vector<AnimationPlot> plots;
  try {
    simulation = prepare_simulation(scenario);
    // output.plots is checked whether or not a page is asked for: it names columns.
    plots = animation_plots(scenario, column_layout(scenario, *simulation->formulation));
  } catch (const ScenarioError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return kInvalidScenario;
  }

  const std::uint64_t fingerprint =
      args.resume.empty() && args.save_state.empty() ? 0 : fingerprint_of(args);
  std::optional<LoadedCheckpoint> resumed;
  if (!args.resume.empty()) {
    resumed = checkpoint_to_resume(args, fingerprint, *simulation);
    if (!resumed) return kBadCommandLine;
  }

  const std::filesystem::path out_dir(args.out_dir);
  const std::filesystem::path trajectory = out_dir / scenario.output.trajectory;
  // Every file the run may write, before it starts: the events file's name counts even when the
  // run may have no events to write.
  std::vector<OutputFile> outputs = {
      {"output.trajectory", scenario.output.trajectory, "the trajectory's file", trajectory,
       scenario.output.trajectory_where},
      {"output.events", scenario.output.events,
       scenario.output.events_given ? "the events file"
                                    : "the events file's name (by default FILE_events.csv)",
       out_dir / scenario.output.events, scenario.output.events_where},
  };
  if (const auto page = animation_path(args, scenario, trajectory)) {
    if (!scenario.output.animation.empty()) {
      outputs.push_back({"output.animation", scenario.output.animation, "the animation page", *page,
                         scenario.output.animation_where});
    } else {
      outputs.push_back({"--animate",
                         page->filename().string(),
                         "the animation page's name (--animate writes it beside the trajectory "
                         "with .html)",
                         *page,
                         {}});
    }
  }
  if (video)
    outputs.push_back({"--video", video->path.string(), "the video's file", video->path, {}});
  if (!args.save_state.empty()) {
    outputs.push_back({"--save-state",
                       args.save_state,
                       "the saved state's file",
                       std::filesystem::path(args.save_state),
                       {}});
  }
  if (const int shared = refuse_shared_outputs(outputs, scenario); shared != kDone) return shared;
  bool trajectory_goes_on = false;  // a resumed run's, after the stopped run's rows
  if (resumed) {
    const std::optional<bool> goes_on =
        continues_trajectory(trajectory, resumed->origin, args.resume);
    if (!goes_on) return kBadCommandLine;
    trajectory_goes_on = *goes_on;
  }
  std::optional<TrajectoryCsvWriter> writer;
  try {
    std::filesystem::create_directories(trajectory.parent_path());
    if (trajectory_goes_on) {
      writer.emplace(trajectory, column_layout(scenario, *simulation->formulation), trajectory);
    } else {
      writer.emplace(trajectory, column_layout(scenario, *simulation->formulation));
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "tumble run: {}\n", e.what());
    return kOutputError;
  }

  // Rows are kept in memory only for the animation page (which the video is drawn from).
  const std::optional<std::filesystem::path> animation = animation_path(args, scenario, trajectory);
  std::optional<RecordedTrajectory> recorded;
  if (animation || video) {
    recorded.emplace(scenario.bodies.size());
    recorded->record_plots(column_layout(scenario, *simulation->formulation), std::move(plots));
  }

  std::vector<RowSink*> sinks = {&*writer};
  if (recorded) sinks.push_back(&*recorded);
  RowFanOut rows(std::move(sinks));
  std::optional<SimulationCheckpoint> checkpoint;
  CheckpointCallback on_checkpoint;
  if (!args.save_state.empty()) {
    simulation->options.checkpoint_after = args.stop_at;
    simulation->options.stop_at_checkpoint = true;
    on_checkpoint = [&](SimulationCheckpoint k) { checkpoint = std::move(k); };
  }
  const SimulationResult result =
      resumed ? resume_simulation(*simulation, resumed->checkpoint, rows, on_checkpoint)
              : run_simulation(*simulation, rows, on_checkpoint);
  const std::vector<AnimationEvent> page_events = animation_events(scenario, result);
  // The events CSV: when the run had events or jumps, or the scenario asks for it.
  std::optional<std::filesystem::path> events;
  if (scenario.output.events_given || !result.contact_events.empty() || !result.jumps.empty() ||
      !result.user_events.empty()) {
    events = out_dir / scenario.output.events;
  }
  std::vector<std::string> checkpoint_lines;
  if (resumed) {
    checkpoint_lines.push_back(fmt::format(
        "resumed        from {} at t = {:.17g} s{}", args.resume, resumed->checkpoint.t(),
        trajectory_goes_on
            ? ": the trajectory goes on from the stopped run's rows"
            : fmt::format(": the trajectory has the {} rows after it (the run's first {} are "
                          "the stopped run's)",
                          writer->rows(), result.rows - writer->rows())));
  }
  try {
    writer->finish();
    if (checkpoint) {
      CheckpointOrigin origin{args.scenario, fingerprint, static_cast<long>(result.rows), 0, 0};
      origin.trajectory_digest = file_digest(trajectory, &origin.trajectory_bytes);
      write_checkpoint_file(args.save_state, *checkpoint, origin);
      checkpoint_lines.push_back(fmt::format(
          "stopped        at t = {:.17g} s (--stop-at {:g}); its state is in {}: `tumble run "
          "{}{} --resume {}{}` goes on as if it had not stopped",
          checkpoint->t(), args.stop_at, args.save_state, args.scenario, sets_text(args),
          args.save_state, args.out_dir == "." ? std::string() : " --out " + args.out_dir));
    } else if (!args.save_state.empty() && result.report.completed) {
      checkpoint_lines.push_back(fmt::format(
          "not stopped    the run ended at t = {:g} s, before --stop-at {:g}: no state saved",
          result.report.t_reached, args.stop_at));
    }
    if (events) {
      std::vector<std::string> contact_names, joint_names;
      for (const ContactSpec& c : scenario.contacts) contact_names.push_back(c.name);
      for (const JointSpec& j : scenario.joints) joint_names.push_back(j.name);
      std::filesystem::create_directories(events->parent_path());
      write_events_csv(*events, contact_names, joint_names, result.contact_events, result.jumps,
                       result.user_events);
    }
    if (animation && recorded->rows() > 0) {
      std::filesystem::create_directories(animation->parent_path());
      write_animation_html(*animation, make_animation_scene(scenario), *recorded, page_events);
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "tumble run: {}\n", e.what());
    return kOutputError;
  }

  // A video that cannot be made leaves the CSV and the page valid: the summary still reports
  // them, then the video's error and its exit status.
  std::optional<std::string> video_line;
  int video_status = kDone;
  std::string video_failure;
  if (video && recorded->rows() > 0) {
    try {
      video_line = make_video(*video, animation, scenario, *recorded, page_events, trajectory);
    } catch (const ChildInterrupted& e) {
      end_by_signal(e.signal_number());  // the temporary page went with the unwinding
    } catch (const std::invalid_argument& e) {
      video_status = kBadCommandLine;
      video_failure = e.what();
    } catch (const std::exception& e) {
      video_status = kOutputError;
      video_failure = fmt::format("no video written to {}: {}", video->path.string(), e.what());
    }
  }
  print_summary(scenario, *simulation, result, trajectory, events, animation, video_line,
                args.digits, checkpoint_lines);
  if (video_status != kDone) {
    fmt::print(stderr, "tumble run: {}\n", video_failure);
    return video_status;
  }
  if (!result.report.completed) {
    fmt::print(stderr, "tumble run: integration failed: {}\n", result.report.failure);
    return kIntegrationFailed;
  }
  return kDone;
}

}  // namespace tumble::cli
