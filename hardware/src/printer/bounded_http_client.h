#pragma once
// One printer request over cpp-httplib, bounded in time and in size, whatever the server does:
// - a total deadline per request (connect, send, reply). cpp-httplib's timeouts are per read and per write,
//   so a reply dripped one byte a second never timed out; a watchdog shuts the socket down at the deadline.
// - a reply of at most kMaxReplyBytes. cpp-httplib keeps a whole body in memory (a 2 GiB body took 8.2 GB);
//   a declared Content-Length above the limit is refused before the body is read, and a body without one
//   is cut off at the limit.
// The requests the links send go through here only; cpp-httplib stays in hardware/src/printer.
#include <httplib.h>

#include <chrono>
#include <cstddef>
#include <vector>
#include <string>

#include "multidir/core/common/result.h"

namespace multidir::hardware {

// No reply MultiDir reads from a printer comes near this (a status reply is about 1 KiB).
constexpr std::size_t kMaxReplyBytes = std::size_t{1} << 20;

struct HttpEndpoint {
  std::string host;
  int port = 0;
  std::string apiKey;  // sent as X-Api-Key when not empty
};

struct HttpReply {
  int status = 0;
  std::string body;
};

// A multipart/form-data part: a plain field (`fileName` empty) or a file.
struct FormPart {
  std::string name;
  std::string content;
  std::string fileName;
  std::string contentType;
};

class BoundedHttpClient {
 public:
  // Each request connects anew (no keep-alive), waits at most `connectTimeout` for the connection and ends
  // by `deadline` after it began.
  BoundedHttpClient(HttpEndpoint endpoint, std::chrono::milliseconds connectTimeout,
                    std::chrono::milliseconds deadline);

  // The whole reply (any HTTP status). Errors, named `where` (the link): DeviceUnreachable when there was no
  // whole reply (refused, reset, the deadline passed: the message says which), DeviceFault when the reply is
  // larger than kMaxReplyBytes; InvalidParameter (nothing sent) for a form part whose name or file name holds
  // a quote, a backslash or a control character.
  core::Result<HttpReply> get(const std::string& path, const std::string& where) const;
  core::Result<HttpReply> post(const std::string& path, const std::string& body, const std::string& contentType,
                               const std::string& where) const;
  core::Result<HttpReply> postForm(const std::string& path, const std::vector<FormPart>& parts,
                                   const std::string& where) const;

  [[nodiscard]] std::chrono::milliseconds deadline() const { return m_deadline; }

 private:
  core::Result<HttpReply> send(httplib::Request request, const std::string& where) const;

  HttpEndpoint m_endpoint;
  std::chrono::milliseconds m_connectTimeout;
  std::chrono::milliseconds m_deadline;
};

// The body of a multipart/form-data request with `boundary`. Errors: InvalidParameter naming `where` for a
// part's name or file name with a quote, a backslash or a control character (they would end the header's
// quoted string or the header itself: a header of the name's choosing), shown escaped.
core::Result<std::string> multipartBody(const std::vector<FormPart>& parts, const std::string& boundary,
                                        const std::string& where);

}  // namespace multidir::hardware
