// Where the binary finds what ships beside it: validation cases (scenes, plot scripts), reference
// data and the plot scripts of compare-piv and psd, laid out as in the source tree. An installed
// valsalva (`cmake --install`) finds them relative to itself, so it works outside its source
// tree (issue 20).
#pragma once

#include <filesystem>

namespace valsalva::run {

// The first of: $VALSALVA_DATA_DIR; <folder of the executable>/../share/valsalva when it holds
// validation/; the source tree the binary was built from. Throws std::runtime_error naming the
// places looked at when none holds validation/.
std::filesystem::path data_dir();

}  // namespace valsalva::run
