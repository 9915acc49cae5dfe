#pragma once
// The simulator's listening socket (IPv4, non-blocking, close-on-exec), with a refusal that says why it
// could not listen in words an operator can act on: another program holds the port, the address is not
// one of this machine's, the port needs root.
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::hardware::sim {

// The listening descriptor. `address` must already be a dotted IPv4 address.
core::Result<int> listenTcp(const std::string& address, int port, int backlog);

// The explanation listenTcp gives for errno `errnum` (exposed for the test of each case).
std::string listenFailure(const std::string& address, int port, int errnum);

}  // namespace multidir::hardware::sim
