// A time series of one solid's results for ParaView: <dir>/<basename>_NNNNNN.h5 per output
// (io/solid_output.hpp: current and reference positions, displacement, extra nodal vectors,
// stresses) and <dir>/<basename>.xmf, an XDMF 3 temporal collection of them rewritten after each
// write (so an interrupted run leaves a readable file). Serial: the solid is replicated on
// every rank and the caller writes from one rank.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "io/solid_output.hpp"

namespace valsalva::io {

class SolidSeries {
 public:
  // `dir` is created when missing. The mesh must outlive the series.
  SolidSeries(std::filesystem::path dir, std::string basename, const structure::SolidMesh& mesh);

  // Writes the step file and rewrites the collection; returns the step file's path.
  std::filesystem::path write(double time, const Eigen::Matrix3Xd& x,
                              const structure::NodalStress* stress,
                              const SolidVectors& vectors = {});

  std::filesystem::path xmf_file() const { return dir_ / (basename_ + ".xmf"); }
  int steps_written() const { return static_cast<int>(grids_.size()); }

 private:
  std::filesystem::path dir_;
  std::string basename_;
  const structure::SolidMesh* mesh_;
  std::vector<std::string> grids_;  // one <Grid> element per step
};

}  // namespace valsalva::io
