#include "run/stop_signal.hpp"

#include <csignal>
#include <stdexcept>

#include "core/comm.hpp"

namespace valsalva::run {

namespace {

volatile std::sig_atomic_t received = 0;
bool installed = false;
struct sigaction previous_int, previous_term;

extern "C" void on_stop_signal(int sig) {
  received = sig;
}

}  // namespace

StopSignal::StopSignal() {
  if (installed) throw std::logic_error("StopSignal: handlers are already installed");
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // a blocking MPI or file call is resumed, not failed
  if (sigaction(SIGINT, &action, &previous_int) != 0 ||
      sigaction(SIGTERM, &action, &previous_term) != 0)
    throw std::runtime_error("StopSignal: sigaction failed");
  installed = true;
}

StopSignal::~StopSignal() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
  installed = false;
}

bool StopSignal::raised_locally() {
  return received != 0;
}
int StopSignal::signal_number() {
  return received;
}
void StopSignal::clear() {
  received = 0;
}

bool StopSignal::requested(MPI_Comm comm) const {
  return core::Comm(comm).any(received != 0);
}

}  // namespace valsalva::run
