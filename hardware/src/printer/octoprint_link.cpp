// OctoPrint's REST API over HTTP with cpp-httplib: the threads and the latch are HttpPrinterLink's; this file
// holds OctoPrint's requests, reply shapes and error codes.
#include "multidir/hardware/octoprint_link.h"

#include <nlohmann/json.hpp>
#include <utility>

#include "printable_text.h"
#include "printer/http_printer_link.h"
#include "printer/octoprint_status.h"
#include "printer/reply_json.h"

namespace multidir::hardware {
namespace {

using Json = nlohmann::json;

constexpr int kConflict = 409;  // OctoPrint: the printer is not operational, or the job is not in a state for it

// OctoPrint's own words from an error reply: {"error": "..."} (its API's JSON errors), else a short plain body.
std::string octoPrintWords(const HttpReply& res) {
  const core::Result<Json> body = parseReplyJson(res.body, "", "", "");
  if (body && body->is_object() && body->contains("error") && (*body)["error"].is_string())
    return escapeControls((*body)["error"].get<std::string>());
  if (!res.body.empty() && res.body.size() <= 200 && res.body.find('<') == std::string::npos)
    return escapeControls(res.body);
  return {};
}

class OctoPrintLink : public HttpPrinterLink {
 public:
  OctoPrintLink(const OctoPrintSettings& settings, PrinterLinkOptions options)
      : HttpPrinterLink("OctoPrint", HttpEndpoint{settings.host, settings.port, settings.apiKey}, std::move(options)) {}
  ~OctoPrintLink() override { disconnect(); }

  std::future<core::Status> pausePrint() override {
    return submit("pausing the print", false, [this](const BoundedHttpClient& client) {
      return postJson(client, "/api/job", {{"command", "pause"}, {"action", "pause"}});
    });
  }
  std::future<core::Status> resumePrint() override {
    return submit("resuming the print", true, [this](const BoundedHttpClient& client) {
      return postJson(client, "/api/job", {{"command", "pause"}, {"action", "resume"}});
    });
  }
  std::future<core::Status> cancelPrint() override {
    return submit("cancelling the print", false, [this](const BoundedHttpClient& client) {
      return postJson(client, "/api/job", {{"command", "cancel"}});
    });
  }
  std::future<core::Status> switchHeatersOff() override {
    return submit("switching the heaters off", false, [this](const BoundedHttpClient& client) {
      return postJson(client, "/api/printer/command", {{"commands", {"M104 S0", "M140 S0"}}});
    });
  }

 protected:
  core::Result<PrinterReading> readStatus(const BoundedHttpClient& client) override {
    const core::Result<Json> job = reply(client.get("/api/job", name()), "GET /api/job");
    if (!job) return job.error();
    const core::Result<OctoPrintJobReading> jobReading = readOctoPrintJob(*job, name());
    if (!jobReading) return jobReading.error();
    const core::Result<HttpReply> printerReply = client.get("/api/printer?exclude=sd", name());
    if (printerReply && printerReply->status == kConflict) return m_tracker.read(*jobReading, nullptr);
    const core::Result<Json> printer = reply(printerReply, "GET /api/printer");
    if (!printer) return printer.error();
    const core::Result<OctoPrintPrinterReading> printerReading = readOctoPrintPrinter(*printer, name());
    if (!printerReading) return printerReading.error();
    return m_tracker.read(*jobReading, &*printerReading);
  }

  // OctoPrint sends M112 ahead of its queue and then closes the serial port. A 409 means OctoPrint has no
  // connection to the printer (it already closed it, after an error or an earlier M112): nothing prints
  // through it, so the stop counts as answered.
  core::Status sendEmergencyStop(const BoundedHttpClient& client) override {
    const core::Result<HttpReply> res =
        client.post("/api/printer/command", Json{{"commands", {"M112"}}}.dump(), "application/json", name());
    if (res && res->status == kConflict) return core::Done{};
    const core::Result<Json> answered = reply(res, "POST /api/printer/command (M112)");
    if (!answered) return answered.error();
    return core::Done{};
  }
  // OctoPrint closed the serial port after M112: connecting again opens it, which resets the printer's board.
  std::future<core::Status> restartFirmware() override {
    return submit("reconnecting OctoPrint to the printer", false, [this](const BoundedHttpClient& client) {
      return postJson(client, "/api/connection", {{"command", "connect"}});
    });
  }
  core::Status postStart(const BoundedHttpClient& client, const std::string& remoteName) override {
    return postJson(client, "/api/files/local/" + percentEncode(remoteName), {{"command", "select"}, {"print", true}});
  }

 private:
  // The reply's JSON (null for 204 No Content), or the error.
  core::Result<Json> reply(const core::Result<HttpReply>& res, const std::string& request) const {
    if (!res && res.error().code != core::ErrorCode::DeviceUnreachable)
      return core::Error{res.error().code, "the reply to " + request + " was refused: " + res.error().message, name()};
    if (!res)
      return core::Error{core::ErrorCode::DeviceUnreachable,
                         "no answer to " + request + " (" + res.error().message +
                             "): check that OctoPrint runs, the address and port (80 on OctoPi, 5000 for "
                             "OctoPrint's own server) and the network",
                         name()};
    const std::string words = octoPrintWords(*res);
    if (res->status == 401 || res->status == 403)
      return core::Error{core::ErrorCode::DeviceFault,
                         "OctoPrint refused " + request + " (HTTP " + std::to_string(res->status) +
                             (words.empty() ? std::string() : ": " + words) +
                             "): the API key is wrong, or its user lacks the permission (status, control, upload, "
                             "print); copy a key from OctoPrint's Settings > Application Keys (or User Settings > "
                             "Application Keys) and give it in a file with --api-key-file (or in MULTIDIR_PRINTER_API_KEY)",
                         name()};
    if (res->status == kConflict)
      return core::Error{core::ErrorCode::DeviceFault,
                         "OctoPrint refused " + request + " (HTTP 409 Conflict" +
                             (words.empty() ? std::string() : ": " + words) +
                             "): the printer is not connected to OctoPrint, or its job is not in a state for this",
                         name()};
    if (res->status < 200 || res->status >= 300)
      return core::Error{core::ErrorCode::DeviceFault,
                         "OctoPrint refused " + request + " (HTTP " + std::to_string(res->status) +
                             (words.empty() ? std::string() : ": " + words) + ")",
                         name()};
    if (res->status == 204 || res->body.empty()) return Json(nullptr);
    return parseReplyJson(res->body, request, ": is this OctoPrint's address?", name());
  }

  core::Status postJson(const BoundedHttpClient& client, const std::string& path, const Json& body) const {
    const core::Result<Json> answered =
        reply(client.post(path, body.dump(), "application/json", name()), "POST " + path + " " + body.dump());
    if (!answered) return answered.error();
    return core::Done{};
  }

  core::Status postFile(const BoundedHttpClient& uploader, const std::string& content, const std::string& remoteName) override {
    const std::vector<FormPart> parts = {{"file", content, remoteName, "application/octet-stream"},
                                         {"select", "false", "", ""},
                                         {"print", "false", "", ""}};
    const core::Result<Json> answered =
        reply(uploader.postForm("/api/files/local", parts, name()), "POST /api/files/local (" + remoteName + ")");
    if (!answered) return answered.error();
    const Json& result = *answered;
    if (!result.is_object() || !result.contains("files") || !result["files"].is_object() ||
        !result["files"].contains("local"))
      return core::Error{
          core::ErrorCode::DeviceFault,
          "the upload of " + remoteName + " was answered without \"files\".\"local\": is this OctoPrint?", name()};
    return core::Done{};
  }

  OctoPrintJobTracker m_tracker;  // the worker's only
};

}  // namespace

core::Result<OctoPrintSettings> parseOctoPrintUrl(const std::string& url) {
  return settingsFromUrl<OctoPrintSettings>(url, "octoprint", 80, 80, "octoprint://192.168.0.21:80");
}

core::Result<std::unique_ptr<PrinterLink>> makeOctoPrintLink(const OctoPrintSettings& settings,
                                                             const PrinterLinkOptions& options) {
  if (core::Status valid = validateEndpoint(settings.host, settings.port, options); !valid) return valid.error();
  if (settings.apiKey.empty())
    return invalidParameter(
        "OctoPrint needs an API key: create one in OctoPrint's Settings > Application Keys (or User Settings > "
        "Application Keys) and give it in a file with --api-key-file (or in MULTIDIR_PRINTER_API_KEY)",
        "--api-key-file");
  return std::unique_ptr<PrinterLink>(std::make_unique<OctoPrintLink>(settings, options));
}

}  // namespace multidir::hardware
