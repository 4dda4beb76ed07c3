// Continuing a run in its own directory from one of its checkpoints (`valsalva run --restart`)
// so that the directory ends up as an uninterrupted run would have left it:
// - the scene may change only in what does not alter the computed history (restart_scene_change),
//   or in the time-step rule, which the restart then reports (restart_step_rule_change);
//   and each restart's scene is recorded next to the first (resolved_scene_restart_<step>.toml);
// - every CSV series the run appends to is cut back to the checkpoint (truncate_series), so rows
//   written after it by the interrupted run are not repeated;
// - field and Lagrangian-mesh series of earlier restarts from this checkpoint or a later one are
//   superseded and removed (superseded_restart_outputs), so the printed "--restart latest"
//   works after any number of crashes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/comm.hpp"
#include "io/appended_series.hpp"
#include "scene/scene.hpp"

namespace valsalva::run {

// Keys a restart may change: time.end, time.max_steps, the time-step rule (time.cfl,
// time.fourier, time.dt: a smaller step to go on past a stretch that diverged, from its last
// good checkpoint), the output intervals and checkpoint settings, run.* (progress and where
// results go), partition.* (results agree to round-off across partitions, as across rank
// counts), and [sample.<name>] sections added or removed (each writes files of its own). Every
// other difference between the recorded scene (the run directory's resolved_scene.toml) and
// `scene` is refused: the message names each key and both values (a key only one of them has
// shows "(absent)"). Empty when none.
std::string restart_scene_change(const std::filesystem::path& recorded, const scene::Scene& scene);

// The time-step rule's changes, "time.cfl 0.1 -> 0.05, ..." (empty when none): the restart is
// then not the bitwise continuation of the run, and says so.
std::string restart_step_rule_change(const std::filesystem::path& recorded,
                                     const scene::Scene& scene);

// Outputs of earlier restarts from checkpoint step >= `step` (fields_restart_<S>.xmf and its
// HDF5 files, structures/<name>_restart_<S>*): they cover times after the checkpoint, which this
// restart computes again.
std::vector<std::filesystem::path> superseded_restart_outputs(const std::filesystem::path& dir,
                                                              std::int64_t step);

// Collective. Prepares run directory `dir` for a restart from the checkpoint at `step` (time,
// dt): every series in `series` (names from appended_series() the scene writes; another name
// throws std::logic_error) must exist and is truncated, the superseded restart outputs are removed,
// and the scene is recorded as resolved_scene_restart_<step>.toml. Rank 0 does the work and prints
// what it cut; an error is thrown on every rank.
void continue_in_place(const std::filesystem::path& dir, const scene::Scene& scene,
                       std::int64_t step, double time, double dt,
                       const std::vector<std::string>& series, const core::Comm& comm);

}  // namespace valsalva::run
