// Errors found by one rank inside a collective operation: every rank calls settle(), which
// throws the same std::runtime_error on all ranks (the message of the lowest failing rank,
// broadcast), so no rank waits alone in a later collective call.
#pragma once

#include <string>

#include "core/comm.hpp"

namespace valsalva::ibm {

void settle(const core::Comm& comm, const std::string& local_error);

}  // namespace valsalva::ibm
