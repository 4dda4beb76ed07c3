/* MPI call counter for the scaling study (validation/bench/scaling_study.py), not part of the
 * solver: a PMPI interposer loaded with LD_PRELOAD that counts, per rank, the calls and bytes of
 * the point-to-point and collective operations valsalva and hypre make. At MPI_Finalize rank r
 * writes "rank,operation,calls,bytes" rows to <VALSALVA_MPI_COUNTS>.<r> (nothing is written when
 * the variable is unset). Bytes are those the calling rank sends (its send buffer; for
 * receives, the posted receive size). The study subtracts two runs of different lengths to get
 * the counts per time step without the set-up. */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>

enum Operation {
  op_send,
  op_isend,
  op_recv,
  op_irecv,
  op_wait,
  op_waitall,
  op_allreduce,
  op_reduce,
  op_bcast,
  op_barrier,
  op_allgather,
  op_allgatherv,
  op_gather,
  op_gatherv,
  op_alltoall,
  op_alltoallv,
  op_scan,
  op_exscan,
  op_count
};

static const char* const names[op_count] = {
    "send",      "isend",   "recv",     "irecv",     "wait",      "waitall",
    "allreduce", "reduce",  "bcast",    "barrier",   "allgather", "allgatherv",
    "gather",    "gatherv", "alltoall", "alltoallv", "scan",      "exscan"};

static long long calls[op_count];
static long long bytes[op_count];

static long long size_of(int count, MPI_Datatype type) {
  int size = 0;
  if (type == MPI_DATATYPE_NULL || PMPI_Type_size(type, &size) != MPI_SUCCESS) return 0;
  return (long long)count * size;
}

static void tally(enum Operation op, long long n) {
  ++calls[op];
  bytes[op] += n;
}

int MPI_Send(const void* buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm) {
  tally(op_send, size_of(count, type));
  return PMPI_Send(buf, count, type, dest, tag, comm);
}

int MPI_Isend(const void* buf, int count, MPI_Datatype type, int dest, int tag, MPI_Comm comm,
              MPI_Request* request) {
  tally(op_isend, size_of(count, type));
  return PMPI_Isend(buf, count, type, dest, tag, comm, request);
}

int MPI_Recv(void* buf, int count, MPI_Datatype type, int source, int tag, MPI_Comm comm,
             MPI_Status* status) {
  tally(op_recv, size_of(count, type));
  return PMPI_Recv(buf, count, type, source, tag, comm, status);
}

int MPI_Irecv(void* buf, int count, MPI_Datatype type, int source, int tag, MPI_Comm comm,
              MPI_Request* request) {
  tally(op_irecv, size_of(count, type));
  return PMPI_Irecv(buf, count, type, source, tag, comm, request);
}

int MPI_Wait(MPI_Request* request, MPI_Status* status) {
  tally(op_wait, 0);
  return PMPI_Wait(request, status);
}

int MPI_Waitall(int count, MPI_Request requests[], MPI_Status statuses[]) {
  tally(op_waitall, 0);
  return PMPI_Waitall(count, requests, statuses);
}

int MPI_Allreduce(const void* send, void* recv, int count, MPI_Datatype type, MPI_Op op,
                  MPI_Comm comm) {
  tally(op_allreduce, size_of(count, type));
  return PMPI_Allreduce(send, recv, count, type, op, comm);
}

int MPI_Reduce(const void* send, void* recv, int count, MPI_Datatype type, MPI_Op op, int root,
               MPI_Comm comm) {
  tally(op_reduce, size_of(count, type));
  return PMPI_Reduce(send, recv, count, type, op, root, comm);
}

int MPI_Bcast(void* buf, int count, MPI_Datatype type, int root, MPI_Comm comm) {
  tally(op_bcast, size_of(count, type));
  return PMPI_Bcast(buf, count, type, root, comm);
}

int MPI_Barrier(MPI_Comm comm) {
  tally(op_barrier, 0);
  return PMPI_Barrier(comm);
}

int MPI_Allgather(const void* send, int send_count, MPI_Datatype send_type, void* recv,
                  int recv_count, MPI_Datatype recv_type, MPI_Comm comm) {
  tally(op_allgather, size_of(send_count, send_type));
  return PMPI_Allgather(send, send_count, send_type, recv, recv_count, recv_type, comm);
}

int MPI_Allgatherv(const void* send, int send_count, MPI_Datatype send_type, void* recv,
                   const int recv_counts[], const int displs[], MPI_Datatype recv_type,
                   MPI_Comm comm) {
  tally(op_allgatherv, size_of(send_count, send_type));
  return PMPI_Allgatherv(send, send_count, send_type, recv, recv_counts, displs, recv_type, comm);
}

int MPI_Gather(const void* send, int send_count, MPI_Datatype send_type, void* recv, int recv_count,
               MPI_Datatype recv_type, int root, MPI_Comm comm) {
  tally(op_gather, size_of(send_count, send_type));
  return PMPI_Gather(send, send_count, send_type, recv, recv_count, recv_type, root, comm);
}

int MPI_Gatherv(const void* send, int send_count, MPI_Datatype send_type, void* recv,
                const int recv_counts[], const int displs[], MPI_Datatype recv_type, int root,
                MPI_Comm comm) {
  tally(op_gatherv, size_of(send_count, send_type));
  return PMPI_Gatherv(send, send_count, send_type, recv, recv_counts, displs, recv_type, root,
                      comm);
}

int MPI_Alltoall(const void* send, int send_count, MPI_Datatype send_type, void* recv,
                 int recv_count, MPI_Datatype recv_type, MPI_Comm comm) {
  int size = 1;
  PMPI_Comm_size(comm, &size);
  tally(op_alltoall, size_of(send_count, send_type) * size);
  return PMPI_Alltoall(send, send_count, send_type, recv, recv_count, recv_type, comm);
}

int MPI_Alltoallv(const void* send, const int send_counts[], const int send_displs[],
                  MPI_Datatype send_type, void* recv, const int recv_counts[],
                  const int recv_displs[], MPI_Datatype recv_type, MPI_Comm comm) {
  int size = 1;
  long long total = 0;
  PMPI_Comm_size(comm, &size);
  for (int r = 0; r < size; ++r) total += size_of(send_counts[r], send_type);
  tally(op_alltoallv, total);
  return PMPI_Alltoallv(send, send_counts, send_displs, send_type, recv, recv_counts, recv_displs,
                        recv_type, comm);
}

int MPI_Scan(const void* send, void* recv, int count, MPI_Datatype type, MPI_Op op, MPI_Comm comm) {
  tally(op_scan, size_of(count, type));
  return PMPI_Scan(send, recv, count, type, op, comm);
}

int MPI_Exscan(const void* send, void* recv, int count, MPI_Datatype type, MPI_Op op,
               MPI_Comm comm) {
  tally(op_exscan, size_of(count, type));
  return PMPI_Exscan(send, recv, count, type, op, comm);
}

int MPI_Finalize(void) {
  const char* path = getenv("VALSALVA_MPI_COUNTS");
  if (path != NULL && path[0] != '\0') {
    int rank = 0;
    PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
    char name[4096];
    snprintf(name, sizeof name, "%s.%d", path, rank);
    FILE* out = fopen(name, "w");
    if (out != NULL) {
      for (int op = 0; op < op_count; ++op)
        if (calls[op] > 0) fprintf(out, "%d,%s,%lld,%lld\n", rank, names[op], calls[op], bytes[op]);
      fclose(out);
    } else {
      fprintf(stderr, "mpi_counts: cannot write %s\n", name);
    }
  }
  return PMPI_Finalize();
}
