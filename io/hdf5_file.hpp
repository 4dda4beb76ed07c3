// A small RAII wrapper over the HDF5 C API for valsalva's parallel output: every identifier is
// closed by its owner, every return code is checked and turned into an exception that names the
// file, the dataset and the failing call. hdf5.h stays out of this header (io links HDF5
// privately); hid_t is std::int64_t in HDF5 >= 1.10, checked in hdf5_file.cpp.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace valsalva::io::h5 {

using Id = std::int64_t;

// Owns one HDF5 identifier and closes it with the matching H5?close.
class Handle {
 public:
  enum class Kind { file, dataset, dataspace, plist, attribute };
  Handle() = default;
  Handle(Id id, Kind kind) : id_(id), kind_(kind) {}
  ~Handle() { reset(); }
  Handle(Handle&& other) noexcept : id_(other.id_), kind_(other.kind_) { other.id_ = -1; }
  Handle& operator=(Handle&& other) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  Id get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  // Closes now; returns the HDF5 status (negative on failure) so callers can report it.
  int reset();

 private:
  Id id_ = -1;
  Kind kind_ = Kind::file;
};

enum class Mode { create, read };

// One HDF5 file. With a communicator it is opened through MPI-IO and every dataset operation
// is collective over that communicator (each rank calls it, possibly with no rows of its own);
// without one it is a plain POSIX file of this process.
class File {
 public:
  File(MPI_Comm comm, std::filesystem::path path, Mode mode);
  File(std::filesystem::path path, Mode mode);
  ~File() = default;
  File(File&&) noexcept = default;
  File& operator=(File&&) noexcept = default;

  const std::filesystem::path& path() const { return path_; }
  bool parallel() const { return parallel_; }

  // Creates dataset `name` of shape [global_rows] (cols == 0) or [global_rows x cols] and writes
  // the rows `row_ids` of this rank (any order, unique over all ranks); `data` holds
  // row_ids.size() rows, row-major. Rows nobody writes stay at the fill value 0. In parallel the
  // rows are first sent to the rank of their block, so each rank writes one contiguous slab.
  template <class T>
  void write_rows(const std::string& name, std::int64_t global_rows, int cols,
                  std::span<const std::int64_t> row_ids, std::span<const T> data);

  // As write_rows for a contiguous block of rows starting at `first_row` (no sorting needed).
  template <class T>
  void write_block(const std::string& name, std::int64_t global_rows, int cols,
                   std::int64_t first_row, std::span<const T> data);

  // Reads rows `row_ids` (any order, duplicates allowed) of dataset `name`; row-major result.
  template <class T>
  std::vector<T> read_rows(const std::string& name, std::span<const std::int64_t> row_ids) const;

  // Reads the whole dataset, row-major.
  template <class T>
  std::vector<T> read_all(const std::string& name) const;

  bool has(const std::string& name) const;
  std::vector<std::int64_t> dims(const std::string& name) const;

  // Scalar double attribute on the root group.
  void write_attribute(const std::string& name, double value);
  double read_attribute(const std::string& name) const;

  // Closes the file, reporting a failure (the destructor closes silently).
  void close();

 private:
  std::filesystem::path path_;
  bool parallel_ = false;
  MPI_Comm comm_ = MPI_COMM_NULL;  // not owned; must outlive the file
  Handle file_;
};

// Collective over `comm`: throws on every rank when any rank has a non-empty error (its own
// message, or "invalid input on another rank"), so that no rank waits alone in a collective call.
void settle(MPI_Comm comm, const std::string& local_error);

// "HDF5 error in <call> (file '<path>', dataset '<name>'): <HDF5's own description>".
[[noreturn]] void fail(const std::string& call, const std::filesystem::path& file,
                       const std::string& dataset);

}  // namespace valsalva::io::h5
