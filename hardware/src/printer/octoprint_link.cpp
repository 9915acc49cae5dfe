// OctoPrint's REST API over HTTP with cpp-httplib: the threads and the latch are HttpPrinterLink's; this file
// holds OctoPrint's requests, reply shapes and error codes.
#include "multidir/hardware/octoprint_link.h"

#include <nlohmann/json.hpp>
#include <utility>

#include "printer/http_printer_link.h"
#include "printer/octoprint_status.h"

namespace multidir::hardware {
namespace {

using Json = nlohmann::json;

constexpr int kConflict = 409;  // OctoPrint: the printer is not operational, or the job is not in a state for it

// OctoPrint's own words from an error reply: {"error": "..."} (its API's JSON errors), else a short plain body.
std::string octoPrintWords(const httplib::Response& res) {
  const Json body = Json::parse(res.body, nullptr, false);
  if (!body.is_discarded() && body.is_object() && body.contains("error") && body["error"].is_string())
    return body["error"].get<std::string>();
  if (!res.body.empty() && res.body.size() <= 200 && res.body.find('<') == std::string::npos) return res.body;
  return {};
}

class OctoPrintLink : public HttpPrinterLink {
 public:
  OctoPrintLink(const OctoPrintSettings& settings, PrinterLinkOptions options)
      : HttpPrinterLink("OctoPrint", HttpEndpoint{settings.host, settings.port, settings.apiKey}, std::move(options)) {}
  ~OctoPrintLink() override { disconnect(); }

  std::future<core::Status> startPrint(const std::string& remoteName) override {
    return submit("starting " + remoteName, true, [this, remoteName](httplib::Client& client) {
      return postJson(client, "/api/files/local/" + percentEncode(remoteName),
                      {{"command", "select"}, {"print", true}});
    });
  }
  std::future<core::Status> pausePrint() override {
    return submit("pausing the print", false, [this](httplib::Client& client) {
      return postJson(client, "/api/job", {{"command", "pause"}, {"action", "pause"}});
    });
  }
  std::future<core::Status> resumePrint() override {
    return submit("resuming the print", true, [this](httplib::Client& client) {
      return postJson(client, "/api/job", {{"command", "pause"}, {"action", "resume"}});
    });
  }
  std::future<core::Status> cancelPrint() override {
    return submit("cancelling the print", false, [this](httplib::Client& client) {
      return postJson(client, "/api/job", {{"command", "cancel"}});
    });
  }
  std::future<core::Status> switchHeatersOff() override {
    return submit("switching the heaters off", false, [this](httplib::Client& client) {
      return postJson(client, "/api/printer/command", {{"commands", {"M104 S0", "M140 S0"}}});
    });
  }

 protected:
  core::Result<PrinterReading> readStatus(httplib::Client& client) override {
    const core::Result<Json> job = reply(client.Get("/api/job"), "GET /api/job");
    if (!job) return job.error();
    const core::Result<OctoPrintJobReading> jobReading = readOctoPrintJob(*job, name());
    if (!jobReading) return jobReading.error();
    const httplib::Result printerReply = client.Get("/api/printer?exclude=sd");
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
  core::Status sendEmergencyStop(httplib::Client& client) override {
    const httplib::Result res =
        client.Post("/api/printer/command", Json{{"commands", {"M112"}}}.dump(), "application/json");
    if (res && res->status == kConflict) return core::Done{};
    const core::Result<Json> answered = reply(res, "POST /api/printer/command (M112)");
    if (!answered) return answered.error();
    return core::Done{};
  }

 private:
  // The reply's JSON (null for 204 No Content), or the error.
  core::Result<Json> reply(const httplib::Result& res, const std::string& request) const {
    if (!res)
      return core::Error{core::ErrorCode::DeviceUnreachable,
                         "no answer to " + request + " (" + httplib::to_string(res.error()) +
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
                             "Application Keys) and pass it with --api-key",
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
    Json body = Json::parse(res->body, nullptr, false);
    if (body.is_discarded())
      return core::Error{core::ErrorCode::DeviceFault,
                         "the reply to " + request + " is not JSON: is this OctoPrint's address?", name()};
    return body;
  }

  core::Status postJson(httplib::Client& client, const std::string& path, const Json& body) const {
    const core::Result<Json> answered =
        reply(client.Post(path.c_str(), body.dump(), "application/json"), "POST " + path + " " + body.dump());
    if (!answered) return answered.error();
    return core::Done{};
  }

  core::Status postFile(httplib::Client& uploader, const std::string& content, const std::string& remoteName) override {
    const httplib::MultipartFormDataItems items = {{"file", content, remoteName, "application/octet-stream"},
                                                   {"select", "false", "", ""},
                                                   {"print", "false", "", ""}};
    const core::Result<Json> answered =
        reply(uploader.Post("/api/files/local", items), "POST /api/files/local (" + remoteName + ")");
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
        "Application Keys) and pass it with --api-key",
        "--api-key");
  return std::unique_ptr<PrinterLink>(std::make_unique<OctoPrintLink>(settings, options));
}

}  // namespace multidir::hardware
