// Seeded random-mutation fuzzing of the text readers (numeric tables, waveforms, probes, PIV CSV
// and Tecplot, reference tables) and the scene loader (issue 23, evidence):
// each good input is mutated (bytes flipped, deleted, duplicated; hostile tokens such as nan,
// 1e999, ",", "=", "[", quotes and line breaks inserted; lines repeated or dropped) a fixed
// number of times with a fixed seed, and each reader must either accept the result or throw its
// documented error (std::runtime_error and its subclasses: TableError, SceneError). A crash, a
// hang, a std::logic_error (out_of_range, invalid_argument: an internal bug) or any other
// exception fails the test. Build with the asan preset to also catch silent memory errors.
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/piv_data.hpp"
#include "analysis/probes.hpp"
#include "core/numeric_table.hpp"
#include "io/waveform_table.hpp"
#include "scene/scene.hpp"

namespace fs = std::filesystem;
using namespace valsalva;

namespace {

const fs::path source = fs::path(VALSALVA_SOURCE_DIR);

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string mutate(std::string text, std::mt19937_64& random) {
  static const std::vector<std::string> tokens{"nan",
                                               "inf",
                                               "-inf",
                                               "1e999",
                                               "-1e-999",
                                               "1e308",
                                               ",",
                                               ",,",
                                               ";",
                                               " ",
                                               "\t",
                                               "\n",
                                               "\r\n",
                                               "=",
                                               "[",
                                               "]",
                                               "{",
                                               "}",
                                               "\"",
                                               "'",
                                               "#",
                                               "0x1p3",
                                               "+",
                                               "-",
                                               ".",
                                               "e",
                                               "ZONE I=3, J=2\n",
                                               "VARIABLES = \"x\", \"y\"\n",
                                               "[mesh]\n",
                                               "source = \"gmsh\"\n",
                                               "cells = [0, 0, 0]\n",
                                               "99999999999999999999",
                                               "\xff\xfe",
                                               std::string(1, '\0')};
  const int edits = 1 + static_cast<int>(random() % 4);
  for (int e = 0; e < edits; ++e) {
    const std::size_t at = text.empty() ? 0 : random() % (text.size() + 1);
    switch (random() % 6) {
      case 0:  // flip a byte
        if (at < text.size()) text[at] = static_cast<char>(random() % 256);
        break;
      case 1:  // delete a run
        if (at < text.size()) text.erase(at, 1 + random() % 8);
        break;
      case 2:  // hostile token
        text.insert(at, tokens[random() % tokens.size()]);
        break;
      case 3: {  // duplicate a line
        const std::size_t a = text.rfind('\n', at == 0 ? 0 : at - 1);
        const std::size_t b = text.find('\n', at);
        const std::size_t begin = a == std::string::npos ? 0 : a + 1;
        const std::size_t end = b == std::string::npos ? text.size() : b + 1;
        if (begin < end) text.insert(begin, text.substr(begin, end - begin));
        break;
      }
      case 4:  // truncate
        text.resize(at);
        break;
      default:  // digit change
        for (std::size_t k = at; k < text.size(); ++k)
          if (text[k] >= '0' && text[k] <= '9') {
            text[k] = static_cast<char>('0' + random() % 10);
            break;
          }
    }
  }
  return text;
}

// Runs `reader` on `iterations` mutations of `seed_file`; counts accepted and refused inputs.
void fuzz(const fs::path& seed_file, int iterations, std::uint64_t seed,
          const std::function<void(const fs::path&)>& reader) {
  const std::string original = read(seed_file);
  REQUIRE_FALSE(original.empty());
  const fs::path dir = fs::temp_directory_path() / ("valsalva_fuzz_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / seed_file.filename();
  std::mt19937_64 random(seed);
  int accepted = 0, refused = 0;
  for (int i = 0; i < iterations; ++i) {
    const std::string input = mutate(original, random);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << input;
    try {
      reader(file);
      ++accepted;
    } catch (const std::logic_error& e) {
      FAIL_CHECK("iteration " << i << ": internal error " << e.what() << "\n--- input:\n" << input);
    } catch (const std::runtime_error&) {
      ++refused;
    }
  }
  fs::remove_all(dir);
  MESSAGE(seed_file.filename().string()
          << ": " << accepted << " accepted, " << refused << " refused");
  CHECK(refused > 0);  // the mutations do reach the error paths
}

}  // namespace

TEST_CASE("fuzzed numeric tables (probe series, waveforms) fail only with core::TableError") {
  for (const char* seed : {"tests/app/data/probes_short.csv", "tests/app/scenes/waveform.csv"}) {
    fuzz(source / seed, 2000, 23, [](const fs::path& f) {
      core::read_numeric_table(f, core::TableHeader::optional);
      core::read_numeric_table(f, core::TableHeader::optional, 2, true);
      analysis::read_probe_csv(f);
      io::read_waveform_table(f);
    });
  }
}

TEST_CASE(
    "fuzzed reference tables (quoted fields, blank-separated) fail only with core::TableError") {
  for (const char* seed : {"validation/refdata/ghia1982_cavity/ghia1982_u_vertical_centreline.csv",
                           "validation/refdata/turek_hron_fsi/turek_hron_reference_values.csv",
                           "validation/refdata/tgv_re1600/spectral_Re1600_512.gdiag"}) {
    fuzz(source / seed, 300, 5, [](const fs::path& f) {
      core::TableFormat quoted;
      quoted.quoted = true;
      quoted.maskable = [](const std::string& name) { return name.size() % 2 == 0; };
      core::read_numeric_table(f, quoted);
      core::read_numeric_table(f, core::TableHeader::none, 4, true);
      // The Turek-Hron reader's way: a header, then fields read one by one.
      core::TableLines lines(f, quoted);
      if (lines.next()) lines.header(lines.fields());
      while (lines.next())
        for (const auto& field : lines.fields()) lines.number(field, "x", true);
    });
  }
}

TEST_CASE("fuzzed PIV files (CSV and Tecplot) fail only with a runtime error") {
  for (const char* seed : {"tests/data/piv/good.csv", "tests/data/piv/good.dat"})
    fuzz(source / seed, 2000, 7, [](const fs::path& f) { analysis::read_piv(f); });
}

TEST_CASE("fuzzed scenes fail only with SceneError") {
  for (const char* seed :
       {"scenes/default.toml", "scenes/poiseuille_pipe.toml", "scenes/flap_channel.toml"})
    fuzz(source / seed, 1000, 11, [](const fs::path& f) {
      try {
        scene::load_scene(f);
      } catch (const scene::SceneError&) {
        throw;
      } catch (const std::exception& e) {
        // Everything the loader rejects must come as a SceneError naming file:line:column.
        throw std::logic_error(std::string("not a SceneError: ") + e.what());
      }
    });
}
