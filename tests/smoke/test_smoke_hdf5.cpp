// Parallel HDF5 smoke test: every rank writes its hyperslab of one dataset with a collective
// MPI-IO transfer (checked to have been collective), then every rank reads the whole dataset
// back; values encode (rank, index), so a misplaced slab cannot pass.
#include <doctest/doctest.h>
#include <hdf5.h>
#include <mpi.h>

#include <filesystem>
#include <string>
#include <vector>

TEST_CASE("parallel HDF5: collective hyperslab write, read back on every rank") {
  MPI_Comm comm = MPI_COMM_WORLD;
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  constexpr hsize_t per_rank = 10;
  const std::string path =
      (std::filesystem::current_path() / ("smoke_hdf5_np" + std::to_string(size) + ".h5")).string();
  auto value = [](int r, hsize_t i) { return 1000.0 * r + double(i) + 0.5; };

  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  REQUIRE(H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL) >= 0);
  hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  REQUIRE(file >= 0);
  const hsize_t total = per_rank * size;
  hid_t filespace = H5Screate_simple(1, &total, nullptr);
  hid_t dset = H5Dcreate2(file, "values", H5T_NATIVE_DOUBLE, filespace, H5P_DEFAULT, H5P_DEFAULT,
                          H5P_DEFAULT);
  REQUIRE(dset >= 0);
  const hsize_t start = per_rank * rank;
  REQUIRE(H5Sselect_hyperslab(filespace, H5S_SELECT_SET, &start, nullptr, &per_rank, nullptr) >= 0);
  hid_t memspace = H5Screate_simple(1, &per_rank, nullptr);
  std::vector<double> mine(per_rank);
  for (hsize_t i = 0; i < per_rank; ++i) mine[i] = value(rank, i);
  hid_t dxpl = H5Pcreate(H5P_DATASET_XFER);
  REQUIRE(H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE) >= 0);
  REQUIRE(H5Dwrite(dset, H5T_NATIVE_DOUBLE, memspace, filespace, dxpl, mine.data()) >= 0);
  H5D_mpio_actual_io_mode_t mode = H5D_MPIO_NO_COLLECTIVE;
  REQUIRE(H5Pget_mpio_actual_io_mode(dxpl, &mode) >= 0);
  CHECK(mode != H5D_MPIO_NO_COLLECTIVE);
  H5Pclose(dxpl);
  H5Sclose(memspace);
  H5Sclose(filespace);
  H5Dclose(dset);
  REQUIRE(H5Fclose(file) >= 0);

  file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl);
  REQUIRE(file >= 0);
  dset = H5Dopen2(file, "values", H5P_DEFAULT);
  REQUIRE(dset >= 0);
  std::vector<double> all(total, -1.0);
  REQUIRE(H5Dread(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, all.data()) >= 0);
  int wrong = 0;
  for (int r = 0; r < size; ++r)
    for (hsize_t i = 0; i < per_rank; ++i) wrong += all[per_rank * r + i] != value(r, i);
  CHECK(wrong == 0);
  H5Dclose(dset);
  H5Fclose(file);
  H5Pclose(fapl);
}
