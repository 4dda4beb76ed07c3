#include "io/hdf5_file.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <type_traits>

namespace valsalva::io::h5 {

static_assert(std::is_same_v<hid_t, Id>, "valsalva expects HDF5 >= 1.10 (64-bit hid_t)");

namespace {

// HDF5 prints its error stack to stderr by default; we report errors ourselves, once.
void silence_hdf5_error_printing() {
  static const bool done = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)done;
}

// Collects the innermost descriptions of the current HDF5 error stack.
herr_t collect_error(unsigned n, const H5E_error2_t* err, void* out) {
  auto& text = *static_cast<std::string*>(out);
  if (n < 2 && err->desc != nullptr) {
    if (!text.empty()) text += "; ";
    text += fmt::format("{}: {}", err->func_name, err->desc);
  }
  return 0;
}

template <class T>
hid_t native_type() {
  if constexpr (std::is_same_v<T, double>) return H5T_NATIVE_DOUBLE;
  if constexpr (std::is_same_v<T, std::int64_t>) return H5T_NATIVE_INT64;
  if constexpr (std::is_same_v<T, std::int32_t>) return H5T_NATIVE_INT32;
  if constexpr (std::is_same_v<T, std::uint8_t>) return H5T_NATIVE_UINT8;
}

struct Run {
  hsize_t start;
  hsize_t count;
};

// Contiguous runs of a sorted list of unique rows.
std::vector<Run> runs_of(std::span<const std::int64_t> sorted_rows) {
  std::vector<Run> runs;
  for (std::int64_t r : sorted_rows) {
    if (!runs.empty() && runs.back().start + runs.back().count == static_cast<hsize_t>(r))
      ++runs.back().count;
    else
      runs.push_back({static_cast<hsize_t>(r), 1});
  }
  return runs;
}

class Context {
 public:
  Context(const std::filesystem::path& file, const std::string& dataset)
      : file_(file), dataset_(dataset) {}
  Id operator()(Id id, const char* call) const {
    if (id < 0) fail(call, file_, dataset_);
    return id;
  }
  void operator()(herr_t status, const char* call) const {
    if (status < 0) fail(call, file_, dataset_);
  }
  [[noreturn]] void error(const std::string& what) const {
    throw std::runtime_error(
        fmt::format("HDF5 file '{}', dataset '{}': {}", file_.string(), dataset_, what));
  }

 private:
  const std::filesystem::path& file_;
  const std::string& dataset_;
};

Handle transfer_list(bool parallel, const Context& check) {
  if (!parallel) return {};
  Handle dxpl(check(H5Pcreate(H5P_DATASET_XFER), "H5Pcreate"), Handle::Kind::plist);
  check(H5Pset_dxpl_mpio(dxpl.get(), H5FD_MPIO_COLLECTIVE), "H5Pset_dxpl_mpio");
  return dxpl;
}

Id plist_or_default(const Handle& h) { return h.valid() ? h.get() : H5P_DEFAULT; }

// Selects the rows of `runs` (all columns) in a [rows x cols] file space.
void select_runs(Id space, std::span<const Run> runs, int cols, const Context& check) {
  if (runs.empty()) {
    check(H5Sselect_none(space), "H5Sselect_none");
    return;
  }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const hsize_t start[2] = {runs[i].start, 0};
    const hsize_t count[2] = {runs[i].count, static_cast<hsize_t>(cols)};
    check(H5Sselect_hyperslab(space, i == 0 ? H5S_SELECT_SET : H5S_SELECT_OR, start, nullptr,
                              count, nullptr),
          "H5Sselect_hyperslab");
  }
}

// A 1D memory space of n values; with n == 0 a one-element space with nothing selected, since
// ranks without data still take part in collective transfers.
Handle memory_space(std::size_t n, const Context& check) {
  const hsize_t size = std::max<hsize_t>(n, 1);
  Handle space(check(H5Screate_simple(1, &size, nullptr), "H5Screate_simple"),
               Handle::Kind::dataspace);
  if (n == 0) check(H5Sselect_none(space.get()), "H5Sselect_none");
  return space;
}

}  // namespace

void fail(const std::string& call, const std::filesystem::path& file,
          const std::string& dataset) {
  std::string detail;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, collect_error, &detail);
  throw std::runtime_error(fmt::format("HDF5 error in {} (file '{}', dataset '{}'){}{}", call,
                                       file.string(), dataset, detail.empty() ? "" : ": ",
                                       detail));
}

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    reset();
    id_ = other.id_;
    kind_ = other.kind_;
    other.id_ = -1;
  }
  return *this;
}

int Handle::reset() {
  if (id_ < 0) return 0;
  herr_t status = 0;
  switch (kind_) {
    case Kind::file: status = H5Fclose(id_); break;
    case Kind::dataset: status = H5Dclose(id_); break;
    case Kind::dataspace: status = H5Sclose(id_); break;
    case Kind::plist: status = H5Pclose(id_); break;
    case Kind::attribute: status = H5Aclose(id_); break;
  }
  id_ = -1;
  return status;
}

File::File(MPI_Comm comm, std::filesystem::path path, Mode mode)
    : path_(std::move(path)), parallel_(true), comm_(comm) {
  silence_hdf5_error_printing();
  const std::string none;
  Context check(path_, none);
  Handle fapl(check(H5Pcreate(H5P_FILE_ACCESS), "H5Pcreate"), Handle::Kind::plist);
  check(H5Pset_fapl_mpio(fapl.get(), comm, MPI_INFO_NULL), "H5Pset_fapl_mpio");
  if (mode == Mode::create) {
    file_ = Handle(check(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()),
                         "H5Fcreate"),
                   Handle::Kind::file);
  } else {
    if (!std::filesystem::exists(path_)) check.error("no such file");
    file_ = Handle(check(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, fapl.get()), "H5Fopen"),
                   Handle::Kind::file);
  }
}

File::File(std::filesystem::path path, Mode mode) : path_(std::move(path)), parallel_(false) {
  silence_hdf5_error_printing();
  const std::string none;
  Context check(path_, none);
  if (mode == Mode::create) {
    file_ = Handle(
        check(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), "H5Fcreate"),
        Handle::Kind::file);
  } else {
    if (!std::filesystem::exists(path_)) check.error("no such file");
    file_ = Handle(check(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "H5Fopen"),
                   Handle::Kind::file);
  }
}

void File::close() {
  if (file_.reset() < 0) fail("H5Fclose", path_, "");
}

namespace {

// Creates the dataset and writes the selected rows; `data` holds them in increasing row order.
template <class T>
void write_runs(Id file, bool parallel, const std::filesystem::path& path,
                const std::string& name, std::int64_t global_rows, int cols,
                std::span<const Run> runs, std::span<const T> data) {
  Context check(path, name);
  const int width = std::max(cols, 1);
  if (global_rows < 0 || cols < 0) check.error(fmt::format("bad shape {} x {}", global_rows, cols));
  std::size_t rows = 0;
  for (const Run& r : runs) {
    if (r.start + r.count > static_cast<hsize_t>(global_rows))
      check.error(fmt::format("row {} outside [0, {})", r.start + r.count - 1, global_rows));
    rows += r.count;
  }
  if (data.size() != rows * width)
    check.error(fmt::format("{} values given for {} rows of {} columns", data.size(), rows, width));
  const hsize_t dims[2] = {static_cast<hsize_t>(global_rows), static_cast<hsize_t>(cols)};
  Handle filespace(check(H5Screate_simple(cols == 0 ? 1 : 2, dims, nullptr), "H5Screate_simple"),
                   Handle::Kind::dataspace);
  Handle dset(check(H5Dcreate2(file, name.c_str(), native_type<T>(), filespace.get(), H5P_DEFAULT,
                               H5P_DEFAULT, H5P_DEFAULT),
                    "H5Dcreate2"),
              Handle::Kind::dataset);
  select_runs(filespace.get(), runs, width, check);
  Handle memspace = memory_space(data.size(), check);
  Handle dxpl = transfer_list(parallel, check);
  const T dummy{};
  check(H5Dwrite(dset.get(), native_type<T>(), memspace.get(), filespace.get(),
                 plist_or_default(dxpl), data.empty() ? &dummy : data.data()),
        "H5Dwrite");
  if (dset.reset() < 0) fail("H5Dclose", path, name);
}

// Every rank of a parallel file must create the same dataset shape.
void check_same_shape(MPI_Comm comm, const std::filesystem::path& path, const std::string& name,
                      std::int64_t global_rows, int cols) {
  if (comm == MPI_COMM_NULL) return;
  Context check(path, name);
  const std::int64_t mine[2] = {global_rows, cols};
  std::int64_t lo[2], hi[2];
  if (MPI_Allreduce(mine, lo, 2, MPI_INT64_T, MPI_MIN, comm) != MPI_SUCCESS ||
      MPI_Allreduce(mine, hi, 2, MPI_INT64_T, MPI_MAX, comm) != MPI_SUCCESS)
    check.error("MPI_Allreduce failed");
  if (lo[0] != hi[0] || lo[1] != hi[1])
    check.error(fmt::format("ranks disagree on the shape: rows {}..{}, columns {}..{}", lo[0],
                            hi[0], lo[1], hi[1]));
}

}  // namespace

template <class T>
void File::write_rows(const std::string& name, std::int64_t global_rows, int cols,
                      std::span<const std::int64_t> row_ids, std::span<const T> data) {
  check_same_shape(comm_, path_, name, global_rows, cols);
  Context check(path_, name);
  const std::size_t width = std::max(cols, 1);
  if (data.size() != row_ids.size() * width)
    check.error(fmt::format("{} values given for {} rows of {} columns", data.size(),
                            row_ids.size(), width));
  // Hyperslab unions are transferred in increasing file order: sort rows, permute the data.
  std::vector<std::size_t> order(row_ids.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return row_ids[a] < row_ids[b]; });
  std::vector<std::int64_t> sorted(row_ids.size());
  std::vector<T> buffer(data.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    sorted[i] = row_ids[order[i]];
    if (sorted[i] < 0) check.error(fmt::format("negative row id {}", sorted[i]));
    if (i > 0 && sorted[i] == sorted[i - 1])
      check.error(fmt::format("row id {} given twice", sorted[i]));
    std::copy_n(data.begin() + order[i] * width, width, buffer.begin() + i * width);
  }
  write_runs<T>(file_.get(), parallel_, path_, name, global_rows, cols, runs_of(sorted), buffer);
}

template <class T>
void File::write_block(const std::string& name, std::int64_t global_rows, int cols,
                       std::int64_t first_row, std::span<const T> data) {
  check_same_shape(comm_, path_, name, global_rows, cols);
  const std::size_t width = std::max(cols, 1);
  std::vector<Run> runs;
  if (!data.empty())
    runs.push_back({static_cast<hsize_t>(first_row), static_cast<hsize_t>(data.size() / width)});
  write_runs<T>(file_.get(), parallel_, path_, name, global_rows, cols, runs, data);
}

std::vector<std::int64_t> File::dims(const std::string& name) const {
  Context check(path_, name);
  if (!has(name)) check.error("no such dataset");
  Handle dset(check(H5Dopen2(file_.get(), name.c_str(), H5P_DEFAULT), "H5Dopen2"),
              Handle::Kind::dataset);
  Handle space(check(H5Dget_space(dset.get()), "H5Dget_space"), Handle::Kind::dataspace);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  check(rank, "H5Sget_simple_extent_ndims");
  std::vector<hsize_t> d(rank);
  check(H5Sget_simple_extent_dims(space.get(), d.data(), nullptr), "H5Sget_simple_extent_dims");
  return {d.begin(), d.end()};
}

bool File::has(const std::string& name) const {
  Context check(path_, name);
  const htri_t exists = H5Lexists(file_.get(), name.c_str(), H5P_DEFAULT);
  check(static_cast<herr_t>(exists), "H5Lexists");
  return exists > 0;
}

template <class T>
std::vector<T> File::read_rows(const std::string& name,
                               std::span<const std::int64_t> row_ids) const {
  Context check(path_, name);
  const std::vector<std::int64_t> shape = dims(name);
  if (shape.empty() || shape.size() > 2) check.error("expected a 1D or 2D dataset");
  const std::size_t width = shape.size() == 2 ? shape[1] : 1;
  std::vector<std::int64_t> unique(row_ids.begin(), row_ids.end());
  std::sort(unique.begin(), unique.end());
  unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
  if (!unique.empty() && (unique.front() < 0 || unique.back() >= shape[0]))
    check.error(fmt::format("row ids {}..{} outside [0, {})", unique.front(), unique.back(),
                            shape[0]));
  Handle dset(check(H5Dopen2(file_.get(), name.c_str(), H5P_DEFAULT), "H5Dopen2"),
              Handle::Kind::dataset);
  Handle filespace(check(H5Dget_space(dset.get()), "H5Dget_space"), Handle::Kind::dataspace);
  select_runs(filespace.get(), runs_of(unique), static_cast<int>(width), check);
  std::vector<T> buffer(unique.size() * width);
  Handle memspace = memory_space(buffer.size(), check);
  Handle dxpl = transfer_list(parallel_, check);
  T dummy{};
  check(H5Dread(dset.get(), native_type<T>(), memspace.get(), filespace.get(),
                plist_or_default(dxpl), buffer.empty() ? &dummy : buffer.data()),
        "H5Dread");
  std::vector<T> out(row_ids.size() * width);
  for (std::size_t i = 0; i < row_ids.size(); ++i) {
    const auto pos = std::lower_bound(unique.begin(), unique.end(), row_ids[i]) - unique.begin();
    std::copy_n(buffer.begin() + pos * width, width, out.begin() + i * width);
  }
  return out;
}

template <class T>
std::vector<T> File::read_all(const std::string& name) const {
  Context check(path_, name);
  const std::vector<std::int64_t> shape = dims(name);
  std::size_t n = 1;
  for (std::int64_t d : shape) n *= static_cast<std::size_t>(d);
  Handle dset(check(H5Dopen2(file_.get(), name.c_str(), H5P_DEFAULT), "H5Dopen2"),
              Handle::Kind::dataset);
  Handle dxpl = transfer_list(parallel_, check);
  std::vector<T> out(n);
  T dummy{};
  check(H5Dread(dset.get(), native_type<T>(), H5S_ALL, H5S_ALL, plist_or_default(dxpl),
                out.empty() ? &dummy : out.data()),
        "H5Dread");
  return out;
}

void File::write_attribute(const std::string& name, double value) {
  Context check(path_, name);
  Handle space(check(H5Screate(H5S_SCALAR), "H5Screate"), Handle::Kind::dataspace);
  Handle attr(check(H5Acreate2(file_.get(), name.c_str(), H5T_NATIVE_DOUBLE, space.get(),
                               H5P_DEFAULT, H5P_DEFAULT),
                    "H5Acreate2"),
              Handle::Kind::attribute);
  check(H5Awrite(attr.get(), H5T_NATIVE_DOUBLE, &value), "H5Awrite");
}

double File::read_attribute(const std::string& name) const {
  Context check(path_, name);
  const htri_t exists = H5Aexists(file_.get(), name.c_str());
  check(static_cast<herr_t>(exists), "H5Aexists");
  if (exists == 0) check.error("no such attribute");
  Handle attr(check(H5Aopen(file_.get(), name.c_str(), H5P_DEFAULT), "H5Aopen"),
              Handle::Kind::attribute);
  double value = 0.0;
  check(H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &value), "H5Aread");
  return value;
}

#define VALSALVA_H5_INSTANTIATE(T)                                                             \
  template void File::write_rows<T>(const std::string&, std::int64_t, int,                     \
                                    std::span<const std::int64_t>, std::span<const T>);        \
  template void File::write_block<T>(const std::string&, std::int64_t, int, std::int64_t,      \
                                     std::span<const T>);                                      \
  template std::vector<T> File::read_rows<T>(const std::string&, std::span<const std::int64_t>) \
      const;                                                                                   \
  template std::vector<T> File::read_all<T>(const std::string&) const;

VALSALVA_H5_INSTANTIATE(double)
VALSALVA_H5_INSTANTIATE(std::int64_t)
VALSALVA_H5_INSTANTIATE(std::int32_t)
VALSALVA_H5_INSTANTIATE(std::uint8_t)

#undef VALSALVA_H5_INSTANTIATE

}  // namespace valsalva::io::h5
