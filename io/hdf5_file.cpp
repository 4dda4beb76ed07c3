#include "io/hdf5_file.hpp"

#include <fmt/format.h>
#include <hdf5.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <type_traits>

#include "core/comm.hpp"

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

// Rows [start, start + count) of a dataset; count == 0 selects nothing.
struct Run {
  hsize_t start = 0;
  hsize_t count = 0;
};

// Scattered rows are first sent to the rank of their block (rank r holds rows
// [rows r / P, rows (r + 1) / P)), which then transfers one contiguous hyperslab: a union of many
// small hyperslabs costs HDF5 1.10 quadratic time (60 s for 100k rows scattered over 2 ranks).
struct BlockLayout {
  std::int64_t rows;
  int ranks;
  std::int64_t start(int r) const { return rows * r / ranks; }
  int owner(std::int64_t row) const {
    int r = static_cast<int>(row * ranks / std::max<std::int64_t>(rows, 1));
    while (r + 1 < ranks && start(r + 1) <= row) ++r;
    while (r > 0 && start(r) > row) --r;
    return r;
  }
  // Rows per destination for rows sorted in increasing order.
  std::vector<int> counts(std::span<const std::int64_t> sorted_rows) const {
    std::vector<int> n(ranks, 0);
    for (std::int64_t row : sorted_rows) ++n[owner(row)];
    return n;
  }
};

// MPI_Alltoallv of consecutive slices of `send` (send_counts[r] elements to rank r, `width`
// values each); returns what arrives, ordered by source rank, and the per-source counts.
// Counts are in rows of one MPI datatype each, not in bytes, so that a rank may send more than
// 2^31 bytes (a checkpoint with whole-mesh statistics: 88 B per node and bin).
template <class U>
std::vector<U> exchange(const core::Comm& comm, std::span<const U> send,
                        std::span<const int> send_counts, std::size_t width,
                        std::vector<int>& recv_counts) {
  const int p = comm.size();
  recv_counts.assign(p, 0);
  VALSALVA_MPI(
      MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, comm.get()));
  auto displacements = [&](std::span<const int> counts, std::vector<int>& displ) {
    displ.assign(p, 0);
    std::int64_t total = 0;
    for (int r = 0; r < p; ++r) {
      displ[r] = static_cast<int>(total);
      total += counts[r];
    }
    if (total > std::numeric_limits<int>::max())
      throw std::runtime_error(
          fmt::format("HDF5 row exchange: {} rows exceed MPI's int counts", total));
    return static_cast<std::size_t>(total);
  };
  std::vector<int> sd, rd;
  displacements(send_counts, sd);
  std::vector<U> recv(displacements(recv_counts, rd) * width);
  MPI_Datatype row;
  VALSALVA_MPI(MPI_Type_contiguous(static_cast<int>(width * sizeof(U)), MPI_BYTE, &row));
  VALSALVA_MPI(MPI_Type_commit(&row));
  const int status = MPI_Alltoallv(send.data(), send_counts.data(), sd.data(), row, recv.data(),
                                   recv_counts.data(), rd.data(), row, comm.get());
  MPI_Type_free(&row);
  VALSALVA_MPI(status);
  return recv;
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

Id plist_or_default(const Handle& h) {
  return h.valid() ? h.get() : H5P_DEFAULT;
}

// Selects the rows of `run` (all columns) in a [rows x cols] file space.
void select_run(Id space, Run run, int cols, const Context& check) {
  if (run.count == 0) {
    check(H5Sselect_none(space), "H5Sselect_none");
    return;
  }
  const hsize_t start[2] = {run.start, 0};
  const hsize_t count[2] = {run.count, static_cast<hsize_t>(cols)};
  check(H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr),
        "H5Sselect_hyperslab");
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

void fail(const std::string& call, const std::filesystem::path& file, const std::string& dataset) {
  std::string detail;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, collect_error, &detail);
  throw std::runtime_error(fmt::format("HDF5 error in {} (file '{}', dataset '{}'){}{}", call,
                                       file.string(), dataset, detail.empty() ? "" : ": ", detail));
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
  // In the order of Handle::Kind.
  static herr_t (*const close[])(hid_t) = {H5Fclose, H5Dclose, H5Sclose, H5Pclose, H5Aclose};
  const herr_t status = close[static_cast<int>(kind_)](id_);
  id_ = -1;
  return status;
}

namespace {
Handle open_file(const std::filesystem::path& path, Mode mode, Id fapl) {
  silence_hdf5_error_printing();
  const std::string none;
  Context check(path, none);
  if (mode == Mode::create)
    return {check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), "H5Fcreate"),
            Handle::Kind::file};
  if (!std::filesystem::exists(path)) check.error("no such file");
  return {check(H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl), "H5Fopen"), Handle::Kind::file};
}
}  // namespace

File::File(MPI_Comm comm, std::filesystem::path path, Mode mode)
    : path_(std::move(path)), parallel_(true), comm_(comm) {
  const std::string none;
  Context check(path_, none);
  Handle fapl(check(H5Pcreate(H5P_FILE_ACCESS), "H5Pcreate"), Handle::Kind::plist);
  check(H5Pset_fapl_mpio(fapl.get(), comm, MPI_INFO_NULL), "H5Pset_fapl_mpio");
  file_ = open_file(path_, mode, fapl.get());
}

File::File(std::filesystem::path path, Mode mode)
    : path_(std::move(path)), parallel_(false), file_(open_file(path_, mode, H5P_DEFAULT)) {}

void File::close() {
  if (file_.reset() < 0) fail("H5Fclose", path_, "");
}

void settle(MPI_Comm comm, const std::string& local_error) {
  const core::Comm world(comm);
  if (world.max(std::int64_t(local_error.empty() ? 0 : 1)) == 0) return;
  throw std::runtime_error(local_error.empty() ? "invalid input on another rank" : local_error);
}

namespace {

// Creates the dataset and writes rows `run` from `data` (run.count rows).
template <class T>
void write_run(Id file, bool parallel, const std::filesystem::path& path, const std::string& name,
               std::int64_t global_rows, int cols, Run run, std::span<const T> data) {
  Context check(path, name);
  const hsize_t dims[2] = {static_cast<hsize_t>(global_rows), static_cast<hsize_t>(cols)};
  Handle filespace(check(H5Screate_simple(cols == 0 ? 1 : 2, dims, nullptr), "H5Screate_simple"),
                   Handle::Kind::dataspace);
  Handle dset(check(H5Dcreate2(file, name.c_str(), native_type<T>(), filespace.get(), H5P_DEFAULT,
                               H5P_DEFAULT, H5P_DEFAULT),
                    "H5Dcreate2"),
              Handle::Kind::dataset);
  select_run(filespace.get(), run, std::max(cols, 1), check);
  Handle memspace = memory_space(data.size(), check);
  Handle dxpl = transfer_list(parallel, check);
  const T dummy{};
  check(H5Dwrite(dset.get(), native_type<T>(), memspace.get(), filespace.get(),
                 plist_or_default(dxpl), data.empty() ? &dummy : data.data()),
        "H5Dwrite");
  if (dset.reset() < 0) fail("H5Dclose", path, name);
}

// Reads rows `run` of an existing dataset into `out` (run.count rows).
template <class T>
void read_run(Id file, bool parallel, const std::filesystem::path& path, const std::string& name,
              int width, Run run, std::span<T> out) {
  Context check(path, name);
  Handle dset(check(H5Dopen2(file, name.c_str(), H5P_DEFAULT), "H5Dopen2"), Handle::Kind::dataset);
  Handle filespace(check(H5Dget_space(dset.get()), "H5Dget_space"), Handle::Kind::dataspace);
  select_run(filespace.get(), run, width, check);
  Handle memspace = memory_space(out.size(), check);
  Handle dxpl = transfer_list(parallel, check);
  T dummy{};
  check(H5Dread(dset.get(), native_type<T>(), memspace.get(), filespace.get(),
                plist_or_default(dxpl), out.empty() ? &dummy : out.data()),
        "H5Dread");
}

// Every rank of a parallel file must create the same dataset shape.
std::string same_shape(MPI_Comm comm, std::int64_t global_rows, int cols) {
  if (comm == MPI_COMM_NULL) return {};
  const core::Comm world(comm);
  const std::int64_t rows_hi = world.max(global_rows), rows_lo = -world.max(-global_rows);
  const std::int64_t cols_hi = world.max(std::int64_t(cols)),
                     cols_lo = -world.max(-std::int64_t(cols));
  if (rows_lo == rows_hi && cols_lo == cols_hi) return {};
  return fmt::format("ranks disagree on the shape: rows {}..{}, columns {}..{}", rows_lo, rows_hi,
                     cols_lo, cols_hi);
}

// The smallest run holding all of the sorted rows.
Run cover(std::span<const std::int64_t> sorted_rows) {
  if (sorted_rows.empty()) return {};
  return {static_cast<hsize_t>(sorted_rows.front()),
          static_cast<hsize_t>(sorted_rows.back() - sorted_rows.front() + 1)};
}

}  // namespace

template <class T>
void File::write_rows(const std::string& name, std::int64_t global_rows, int cols,
                      std::span<const std::int64_t> row_ids, std::span<const T> data) {
  const std::size_t width = std::max(cols, 1);
  auto where = [&](const std::string& what) {
    return fmt::format("HDF5 file '{}', dataset '{}': {}", path_.string(), name, what);
  };
  std::string error = same_shape(comm_, global_rows, cols);
  if (error.empty() && (global_rows < 0 || cols < 0))
    error = fmt::format("bad shape {} x {}", global_rows, cols);
  if (error.empty() && data.size() != row_ids.size() * width)
    error = fmt::format("{} values given for {} rows of {} columns", data.size(), row_ids.size(),
                        width);
  // Rows in increasing order (hyperslabs are transferred in file order). Callers mostly pass
  // them so (field output, checkpoints): then the data are used in place, since every copy of a
  // checkpoint with whole-mesh statistics costs gigabytes; otherwise sorted, data permuted alike.
  std::span<const std::int64_t> sorted = row_ids;
  std::span<const T> values = data;
  std::vector<std::int64_t> sorted_rows;
  std::vector<T> permuted;
  if (error.empty() && !std::is_sorted(row_ids.begin(), row_ids.end())) {
    std::vector<std::size_t> order(row_ids.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return row_ids[a] < row_ids[b]; });
    sorted_rows.resize(order.size());
    permuted.resize(data.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
      sorted_rows[i] = row_ids[order[i]];
      std::copy_n(data.begin() + order[i] * width, width, permuted.begin() + i * width);
    }
    sorted = sorted_rows, values = permuted;
  }
  for (std::size_t i = 0; i < sorted.size() && error.empty(); ++i) {
    if (sorted[i] < 0 || sorted[i] >= global_rows)
      error = fmt::format("row id {} outside [0, {})", sorted[i], global_rows);
    else if (i > 0 && sorted[i] == sorted[i - 1])
      error = fmt::format("row id {} given twice", sorted[i]);
  }
  if (parallel_) settle(comm_, error.empty() ? error : where(error));
  if (!error.empty()) throw std::runtime_error(where(error));

  Run run = cover(sorted);
  if (parallel_) {
    const core::Comm world(comm_);
    const BlockLayout layout{global_rows, world.size()};
    run = {static_cast<hsize_t>(layout.start(world.rank())),
           static_cast<hsize_t>(layout.start(world.rank() + 1) - layout.start(world.rank()))};
    if (world.size() > 1) {  // one rank keeps its rows: nothing to send
      const std::vector<int> counts = layout.counts(sorted);
      std::vector<int> recv_counts;
      auto ids = exchange<std::int64_t>(world, sorted, counts, 1, recv_counts);
      auto received = exchange<T>(world, values, counts, width, recv_counts);
      std::vector<T>().swap(permuted);  // free before the block is filled
      sorted_rows = std::move(ids), permuted = std::move(received);
      sorted = sorted_rows, values = permuted;
    }
  }
  // Rows that are exactly the run, in order, are written as they are; otherwise gaps (rows
  // nobody writes) take the fill value 0 in a block.
  bool whole = sorted.size() == run.count;
  for (std::size_t i = 0; i < sorted.size() && whole; ++i)
    whole = static_cast<hsize_t>(sorted[i]) == run.start + i;
  if (!whole) {
    std::vector<T> block(run.count * width, T{});
    std::vector<char> seen(run.count, 0);
    for (std::size_t i = 0; i < sorted.size(); ++i) {
      const std::size_t row = sorted[i] - run.start;
      if (seen[row]++ != 0 && error.empty())
        error = where(fmt::format("row id {} given by two ranks", sorted[i]));
      std::copy_n(values.begin() + i * width, width, block.begin() + row * width);
    }
    std::vector<T>().swap(permuted);
    permuted = std::move(block);
    values = permuted;
  }
  if (parallel_) settle(comm_, error);
  write_run<T>(file_.get(), parallel_, path_, name, global_rows, cols, run, values);
}

template <class T>
void File::write_block(const std::string& name, std::int64_t global_rows, int cols,
                       std::int64_t first_row, std::span<const T> data) {
  const std::size_t width = std::max(cols, 1);
  std::string error = same_shape(comm_, global_rows, cols);
  const auto rows = static_cast<std::int64_t>(data.size() / width);
  if (error.empty() &&
      (data.size() % width != 0 || first_row < 0 || first_row + rows > global_rows))
    error = fmt::format("block of {} values at row {} does not fit {} rows of {} columns",
                        data.size(), first_row, global_rows, width);
  if (!error.empty())
    error = fmt::format("HDF5 file '{}', dataset '{}': {}", path_.string(), name, error);
  if (parallel_) settle(comm_, error);
  if (!error.empty()) throw std::runtime_error(error);
  const Run run{static_cast<hsize_t>(first_row), static_cast<hsize_t>(rows)};
  write_run<T>(file_.get(), parallel_, path_, name, global_rows, cols, rows > 0 ? run : Run{},
               data);
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
  const std::vector<std::int64_t> shape = dims(name);
  std::vector<std::int64_t> unique(row_ids.begin(), row_ids.end());
  std::sort(unique.begin(), unique.end());
  unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
  std::string error;
  if (shape.empty() || shape.size() > 2)
    error = "expected a 1D or 2D dataset";
  else if (!unique.empty() && (unique.front() < 0 || unique.back() >= shape[0]))
    error = fmt::format("row ids {}..{} outside [0, {})", unique.front(), unique.back(), shape[0]);
  if (!error.empty())
    error = fmt::format("HDF5 file '{}', dataset '{}': {}", path_.string(), name, error);
  if (parallel_) settle(comm_, error);
  if (!error.empty()) throw std::runtime_error(error);
  const std::size_t width = shape.size() == 2 ? shape[1] : 1;
  const int cols = static_cast<int>(width);

  std::vector<T> values(unique.size() * width);  // rows of `unique`
  if (!parallel_) {
    const Run run = cover(unique);
    std::vector<T> block(run.count * width);
    read_run<T>(file_.get(), false, path_, name, cols, run, block);
    for (std::size_t i = 0; i < unique.size(); ++i)
      std::copy_n(block.begin() + (unique[i] - run.start) * width, width,
                  values.begin() + i * width);
  } else {  // ask each block's rank for its rows; answers come back in the order asked
    const core::Comm world(comm_);
    const BlockLayout layout{shape[0], world.size()};
    const std::vector<int> counts = layout.counts(unique);
    std::vector<int> asked_counts, answer_counts;
    const auto asked = exchange<std::int64_t>(world, unique, counts, 1, asked_counts);
    std::vector<std::int64_t> sorted_asked = asked;
    std::sort(sorted_asked.begin(), sorted_asked.end());
    const Run run = cover(sorted_asked);
    std::vector<T> block(run.count * width);
    read_run<T>(file_.get(), true, path_, name, cols, run, block);
    std::vector<T> answers(asked.size() * width);
    for (std::size_t i = 0; i < asked.size(); ++i)
      std::copy_n(block.begin() + (asked[i] - run.start) * width, width,
                  answers.begin() + i * width);
    values = exchange<T>(world, answers, asked_counts, width, answer_counts);
  }
  std::vector<T> out(row_ids.size() * width);
  for (std::size_t i = 0; i < row_ids.size(); ++i) {
    const auto pos = std::lower_bound(unique.begin(), unique.end(), row_ids[i]) - unique.begin();
    std::copy_n(values.begin() + pos * width, width, out.begin() + i * width);
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

#define VALSALVA_H5_INSTANTIATE(T)                                                              \
  template void File::write_rows<T>(const std::string&, std::int64_t, int,                      \
                                    std::span<const std::int64_t>, std::span<const T>);         \
  template void File::write_block<T>(const std::string&, std::int64_t, int, std::int64_t,       \
                                     std::span<const T>);                                       \
  template std::vector<T> File::read_rows<T>(const std::string&, std::span<const std::int64_t>) \
      const;                                                                                    \
  template std::vector<T> File::read_all<T>(const std::string&) const;

VALSALVA_H5_INSTANTIATE(double)
VALSALVA_H5_INSTANTIATE(std::int64_t)
VALSALVA_H5_INSTANTIATE(std::int32_t)
VALSALVA_H5_INSTANTIATE(std::uint8_t)

#undef VALSALVA_H5_INSTANTIATE

}  // namespace valsalva::io::h5
