// Moonraker over HTTP with cpp-httplib: the threads and the latch are HttpPrinterLink's; this file holds
// Moonraker's requests and reply shapes.
#include "multidir/hardware/moonraker_link.h"

#include <nlohmann/json.hpp>
#include <utility>

#include "printer/http_printer_link.h"
#include "printer/moonraker_status.h"

namespace multidir::hardware {
namespace {

using Json = nlohmann::json;

class MoonrakerLink : public HttpPrinterLink {
 public:
  MoonrakerLink(const MoonrakerSettings& settings, PrinterLinkOptions options)
      : HttpPrinterLink(HttpEndpoint{settings.host, settings.port, settings.apiKey}, std::move(options),
                        "Moonraker printer at " + settings.host + ":" + std::to_string(settings.port)) {}
  ~MoonrakerLink() override { disconnect(); }

  std::future<core::Status> upload(const std::string& localPath, const std::string& remoteName) override {
    if (const std::string problem = plainFileNameProblem(remoteName); !problem.empty())
      return readyStatus(invalidParameter(problem, name()));
    return submit("uploading " + remoteName, true,
                  [this, localPath, remoteName](httplib::Client&) { return doUpload(localPath, remoteName); });
  }
  std::future<core::Status> startPrint(const std::string& remoteName) override {
    return submit("starting " + remoteName, true, [this, remoteName](httplib::Client& client) {
      return post(client, "/printer/print/start?filename=" + percentEncode(remoteName));
    });
  }
  std::future<core::Status> pausePrint() override {
    return submit("pausing the print", false,
                  [this](httplib::Client& client) { return post(client, "/printer/print/pause"); });
  }
  std::future<core::Status> resumePrint() override {
    return submit("resuming the print", true,
                  [this](httplib::Client& client) { return post(client, "/printer/print/resume"); });
  }
  std::future<core::Status> cancelPrint() override {
    return submit("cancelling the print", false,
                  [this](httplib::Client& client) { return post(client, "/printer/print/cancel"); });
  }

 protected:
  core::Result<PrinterReading> readStatus(httplib::Client& client) override {
    const std::string path = "/printer/objects/query?webhooks&print_stats&virtual_sdcard&extruder&heater_bed";
    const core::Result<Json> answered = reply(client.Get(path.c_str()), "GET " + path);
    if (!answered) return answered.error();
    return readMoonrakerStatus(*answered, name());
  }
  core::Status sendEmergencyStop(httplib::Client& client) override { return post(client, "/printer/emergency_stop"); }

 private:
  // The reply's "result" (Moonraker wraps every successful reply in {"result": ...}), or the error.
  core::Result<Json> reply(const httplib::Result& res, const std::string& request) const {
    if (!res)
      return core::Error{core::ErrorCode::DeviceUnreachable,
                         "no answer to " + request + " (" + httplib::to_string(res.error()) +
                             "): check that Moonraker runs, the address and the network",
                         name()};
    Json body = Json::parse(res->body, nullptr, false);
    if (res->status < 200 || res->status >= 300) {
      std::string message = "HTTP " + std::to_string(res->status);
      if (!body.is_discarded() && body.contains("error") && body["error"].is_object() &&
          body["error"].contains("message") && body["error"]["message"].is_string())
        message += ": " + body["error"]["message"].get<std::string>();
      return core::Error{core::ErrorCode::DeviceFault, "the printer refused " + request + " (" + message + ")", name()};
    }
    if (body.is_discarded())
      return core::Error{core::ErrorCode::DeviceFault,
                         "the reply to " + request + " is not JSON: is this Moonraker's address?", name()};
    if (body.is_object() && body.contains("result")) return body["result"];
    return body;  // Moonraker before 2021 answered uploads without the wrapper
  }

  core::Status post(httplib::Client& client, const std::string& path) const {
    const core::Result<Json> answered = reply(client.Post(path.c_str()), "POST " + path);
    if (!answered) return answered.error();
    return core::Done{};
  }

  core::Status doUpload(const std::string& localPath, const std::string& remoteName) const {
    const core::Result<std::string> content = readFileToUpload(localPath);
    if (!content) return content.error();
    auto uploader = client(options().uploadTimeout);
    const httplib::MultipartFormDataItems items = {{"file", *content, remoteName, "application/octet-stream"},
                                                   {"root", "gcodes", "", ""}};
    const core::Result<Json> answered =
        reply(uploader->Post("/server/files/upload", items), "POST /server/files/upload (" + remoteName + ")");
    if (!answered) return answered.error();
    const Json& result = *answered;
    if (!result.is_object() || !result.contains("item") || !result["item"].is_object())
      return core::Error{core::ErrorCode::DeviceFault,
                         "the upload of " + remoteName + " was answered without an \"item\": is this Moonraker?",
                         name()};
    return core::Done{};
  }
};

}  // namespace

core::Result<MoonrakerSettings> parseMoonrakerUrl(const std::string& url) {
  const core::Result<HostPort> parsed = parseHostPortUrl(url, "moonraker", 80, 7125, "http://192.168.0.20:7125");
  if (!parsed) return parsed.error();
  MoonrakerSettings settings;
  settings.host = parsed->host;
  settings.port = parsed->port;
  return settings;
}

core::Result<std::unique_ptr<PrinterLink>> makeMoonrakerLink(const MoonrakerSettings& settings,
                                                             const PrinterLinkOptions& options) {
  if (settings.host.empty()) return invalidParameter("the printer's host is empty", "printer");
  if (settings.port < 1 || settings.port > 65535) return invalidParameter("the printer's port must be 1..65535", "printer");
  if (core::Status valid = validate(options); !valid) return valid.error();
  return std::unique_ptr<PrinterLink>(std::make_unique<MoonrakerLink>(settings, options));
}

}  // namespace multidir::hardware
