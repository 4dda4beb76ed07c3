// Scene keys of a run as a whole: where results go and how often progress is printed.
#include "scene/scene_keys.hpp"

namespace valsalva::scene {

void declare_run_keys(Schema& s) {
  s.section("run", "Where results go and how the run reports progress.");
  s.string("run.output_dir")
      .def("")
      .note("\"runs/<scene file stem>\"")
      .unit_of("-")
      .doc(
          "Run directory for all results; empty means runs/<scene file stem> (see "
          "run/run_directory.hpp)");
  s.boolean("run.overwrite")
      .def(false)
      .unit_of("-")
      .doc(
          "Allow reusing a non-empty run directory (same as --overwrite): only one whose "
          "valsalva_run.toml names it, and then only the files and folders valsalva writes are "
          "deleted; any other entry there is listed and the run refused");
  s.integer("run.log_every")
      .def(10)
      .at_least(1)
      .unit_of("-")
      .doc("Print a progress line (and write a log.csv row) every this many time steps");
  s.choice("run.progress", {"auto", "status", "lines", "quiet"})
      .def("auto")
      .unit_of("-")
      .doc(
          "status: one line updated in place (cycle, phase, time, ETA, node-steps/s); lines: one "
          "line per log_every steps; quiet: start and end only (`valsalva run --quiet`); auto: "
          "status on a terminal, lines otherwise and under mpiexec");
}

}  // namespace valsalva::scene
