// Run directories: created collectively, resolved_scene.toml written, a non-empty directory
// refused without overwrite, and with it only valsalva's own entries of a directory its marker
// names are cleared. Runs at 1 and 2 ranks.
#include <doctest/doctest.h>
#include <mpi.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "run/run_directory.hpp"

namespace fs = std::filesystem;
using namespace valsalva;

namespace {

// One scratch folder per test run, named by rank 0's pid and shared with the other ranks.
fs::path scratch() {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  long pid = rank == 0 ? static_cast<long>(getpid()) : 0;
  MPI_Bcast(&pid, 1, MPI_LONG, 0, MPI_COMM_WORLD);
  return fs::temp_directory_path() /
         ("valsalva_run_dir_test_" + std::to_string(pid) + "_np" + std::to_string(size));
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void barrier() {
  MPI_Barrier(MPI_COMM_WORLD);
}

}  // namespace

TEST_CASE("prepare creates the directory, writes the resolved scene, and guards old results") {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const fs::path root = scratch();
  if (rank == 0) fs::remove_all(root);
  barrier();
  const scene::Scene scene = scene::parse_scene("[mesh]\nsource = \"box\"\n", "cube.toml");
  const fs::path dir = root / "runs" / "cube";

  const run::RunDirectory run = run::RunDirectory::prepare(dir, false, scene, MPI_COMM_WORLD);
  CHECK(run.path() == dir);
  CHECK(run.file("fields.h5") == dir / "fields.h5");
  CHECK(fs::is_directory(dir));
  CHECK(read(dir / "resolved_scene.toml") == scene.resolved());
  // The saved scene is itself a valid scene that resolves to the same values.
  CHECK(scene::load_scene(dir / "resolved_scene.toml").table() == scene.table());

  // Now non-empty: refused on every rank with a message naming the path and the way out.
  barrier();
  try {
    run::RunDirectory::prepare(dir, false, scene, MPI_COMM_WORLD);
    FAIL_CHECK("a non-empty run directory was reused without overwrite");
  } catch (const run::RunDirectoryError& e) {
    const std::string m = e.what();
    CHECK(m.find("'" + dir.string() + "' is not empty") != std::string::npos);
    CHECK(m.find("--overwrite") != std::string::npos);
    CHECK(m.find("run.overwrite") != std::string::npos);
  }

  // With overwrite valsalva's own results go (files and folders it writes).
  const std::string marker = read(dir / "valsalva_run.toml");
  CHECK(marker.find("directory = \"" + fs::weakly_canonical(fs::absolute(dir)).string() + "\"") !=
        std::string::npos);
  if (rank == 0) {
    for (const char* name : {"log.csv", "fields_000003.h5", "sections.csv", "valve.csv",
                             "valve_cycles.csv", "outlets.csv"})
      std::ofstream(dir / name) << "old";
    fs::create_directories(dir / "checkpoints");
    std::ofstream(dir / "checkpoints" / "checkpoint_000000008.h5") << "old";
  }
  barrier();
  run::RunDirectory::prepare(dir, true, scene, MPI_COMM_WORLD);
  CHECK_FALSE(fs::exists(dir / "log.csv"));
  CHECK_FALSE(fs::exists(dir / "fields_000003.h5"));
  for (const char* name : {"sections.csv", "valve.csv", "valve_cycles.csv", "outlets.csv"})
    CHECK_FALSE(fs::exists(dir / name));
  CHECK_FALSE(fs::exists(dir / "checkpoints"));
  CHECK(fs::exists(dir / "resolved_scene.toml"));
  // A new run, a new identity.
  CHECK(read(dir / "valsalva_run.toml") != marker);

  // Anything valsalva did not write makes --overwrite refuse, listing it, and nothing goes.
  barrier();  // every rank has checked the cleared directory before rank 0 writes into it
  if (rank == 0) {
    std::ofstream(dir / "log.csv") << "old";
    std::ofstream(dir / "notes.txt") << "mine";
    fs::create_directories(dir / "paper");
  }
  barrier();
  CHECK_THROWS_WITH_AS(run::RunDirectory::prepare(dir, true, scene, MPI_COMM_WORLD),
                       doctest::Contains("entries valsalva did not write: notes.txt, paper"),
                       run::RunDirectoryError);
  CHECK(read(dir / "notes.txt") == "mine");
  CHECK(fs::exists(dir / "log.csv"));

  // A folder with a copied scene (no marker) or a copied marker (naming another folder) is a
  // user's folder: never cleared, even with overwrite.
  const fs::path other = root / "not_a_run";
  barrier();
  if (rank == 0) {
    fs::create_directories(other);
    std::ofstream(other / "thesis.tex") << "precious";
    fs::copy_file(dir / "resolved_scene.toml", other / "resolved_scene.toml");
  }
  barrier();
  CHECK_THROWS_WITH_AS(run::RunDirectory::prepare(other, true, scene, MPI_COMM_WORLD),
                       doctest::Contains("holds no valsalva marker valsalva_run.toml"),
                       run::RunDirectoryError);
  barrier();
  if (rank == 0) fs::copy_file(dir / "valsalva_run.toml", other / "valsalva_run.toml");
  barrier();
  const std::string written_for =
      "was written for '" + fs::weakly_canonical(fs::absolute(dir)).string();
  CHECK_THROWS_WITH_AS(run::RunDirectory::prepare(other, true, scene, MPI_COMM_WORLD),
                       doctest::Contains(written_for.c_str()), run::RunDirectoryError);
  CHECK(read(other / "thesis.tex") == "precious");

  // An existing empty directory is fine without overwrite.
  const fs::path empty = root / "empty";
  barrier();
  if (rank == 0) fs::create_directories(empty);
  barrier();
  CHECK_NOTHROW(run::RunDirectory::prepare(empty, false, scene, MPI_COMM_WORLD));
  barrier();
  if (rank == 0) fs::remove_all(root);
}

TEST_CASE("the default run path is runs/<scene file stem>") {
  const scene::Scene unnamed =
      scene::parse_scene("[mesh]\nsource = \"box\"\n", "scenes/cavity.toml");
  CHECK(run::default_run_path(unnamed) == fs::path("runs/cavity"));
  const scene::Scene named = scene::parse_scene(
      "[run]\noutput_dir = \"out/a\"\n[mesh]\nsource = \"box\"\n", "scenes/cavity.toml");
  CHECK(run::default_run_path(named) == fs::path("out/a"));
}
