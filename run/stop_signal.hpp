// SIGINT/SIGTERM turned into a polite stop request: the handler only sets a flag (the one thing
// a signal handler may safely do); the run loop polls it once per step with a collective OR so
// that every rank stops at the same step, writes a checkpoint and exits cleanly.
//
// How the run loop uses it:
//   run::StopSignal stop;                       // installs the handlers, restores them on scope
//   exit for (...) { step(); if (stop.requested(comm)) { ckpt.write(...); break; } }
#pragma once

#include <mpi.h>

namespace valsalva::run {

class StopSignal {
 public:
  StopSignal();  // installs handlers for SIGINT and SIGTERM (only one StopSignal at a time)
  ~StopSignal();
  StopSignal(const StopSignal&) = delete;
  StopSignal& operator=(const StopSignal&) = delete;

  // This process has received SIGINT or SIGTERM (no communication).
  static bool raised_locally();
  // The signal received (0 if none).
  static int signal_number();
  // Collective over `comm`: true on every rank when any rank received a signal.
  bool requested(MPI_Comm comm) const;
  // Forgets a received signal (e.g. after the checkpoint, when a run continues).
  static void clear();
};

}  // namespace valsalva::run
