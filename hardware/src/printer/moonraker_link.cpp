// Moonraker over HTTP with cpp-httplib: the threads and the latch are HttpPrinterLink's; this file holds
// Moonraker's requests and reply shapes.
#include "multidir/hardware/moonraker_link.h"

#include <future>
#include <memory>
#include <nlohmann/json.hpp>
#include <utility>

#include "printable_text.h"
#include "printer/http_printer_link.h"
#include "printer/moonraker_status.h"
#include "printer/reply_json.h"

namespace multidir::hardware {
namespace {

using Json = nlohmann::json;

class MoonrakerLink : public HttpPrinterLink {
 public:
  MoonrakerLink(const MoonrakerSettings& settings, PrinterLinkOptions options)
      : HttpPrinterLink("Moonraker", HttpEndpoint{settings.host, settings.port, settings.apiKey}, std::move(options)) {}
  ~MoonrakerLink() override { disconnect(); }

  std::future<core::Status> pausePrint() override {
    return submit("pausing the print", false,
                  [this](const BoundedHttpClient& client) { return post(client, "/printer/print/pause"); });
  }
  std::future<core::Status> resumePrint() override {
    return submit("resuming the print", true,
                  [this](const BoundedHttpClient& client) { return post(client, "/printer/print/resume"); });
  }
  std::future<core::Status> cancelPrint() override {
    return submit("cancelling the print", false,
                  [this](const BoundedHttpClient& client) { return post(client, "/printer/print/cancel"); });
  }
  // Klipper's TURN_OFF_HEATERS: every heater, whatever printer.cfg names them (M140 fails without a heater_bed).
  std::future<core::Status> switchHeatersOff() override {
    return submit("switching the heaters off", false, [this](const BoundedHttpClient& client) {
      return post(client, "/printer/gcode/script?script=TURN_OFF_HEATERS");
    });
  }

  // Klipper's FIRMWARE_RESTART: out of "shutdown" (after an emergency stop) back to "ready".
  std::future<core::Status> restartFirmware() override {
    return submit("restarting the firmware", false,
                  [this](const BoundedHttpClient& client) { return post(client, "/printer/firmware_restart"); });
  }
  // Klipper's loaded objects: each [manual_stepper NAME] is the object "manual_stepper NAME".
  std::future<core::Result<FirmwareAxes>> readFirmwareAxes() override {
    auto answer = std::make_shared<std::promise<core::Result<FirmwareAxes>>>();
    std::future<core::Result<FirmwareAxes>> future = answer->get_future();
    std::future<core::Status> asked =
        submit("listing the printer's objects", false, [this, answer](const BoundedHttpClient& client) {
          const std::string path = "/printer/objects/list";
          const core::Result<Json> answered = reply(client.get(path, name()), "GET " + path);
          if (!answered) {
            answer->set_value(answered.error());
            return core::Status(answered.error());
          }
          if (!answered->is_object() || !answered->contains("objects") || !(*answered)["objects"].is_array()) {
            const core::Error error{core::ErrorCode::DeviceFault,
                                    "the reply to GET " + path + " has no \"objects\" list: is this Moonraker?",
                                    name()};
            answer->set_value(error);
            return core::Status(error);
          }
          FirmwareAxes axes;
          const std::string prefix = "manual_stepper ";
          for (const Json& object : (*answered)["objects"])
            if (object.is_string() && object.get<std::string>().rfind(prefix, 0) == 0)
              axes.manualSteppers.push_back(object.get<std::string>().substr(prefix.size()));
          answer->set_value(axes);
          return core::Status(core::Done{});
        });
    // A command the link refused or cancelled before it ran never reaches the lambda: its error answers.
    return std::async(std::launch::async, [asked = std::move(asked), future = std::move(future)]() mutable {
      const core::Status status = asked.get();
      if (!status && future.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
        return core::Result<FirmwareAxes>(status.error());
      return future.get();
    });
  }

 protected:
  core::Result<PrinterReading> readStatus(const BoundedHttpClient& client) override {
    const std::string path = "/printer/objects/query?webhooks&print_stats&virtual_sdcard&extruder&heater_bed";
    const core::Result<Json> answered = reply(client.get(path, name()), "GET " + path);
    if (!answered) return answered.error();
    return readMoonrakerStatus(*answered, name());
  }
  core::Status sendEmergencyStop(const BoundedHttpClient& client) override {
    return post(client, "/printer/emergency_stop");
  }
  core::Status postStart(const BoundedHttpClient& client, const std::string& remoteName) override {
    return post(client, "/printer/print/start?filename=" + percentEncode(remoteName));
  }

 private:
  // The reply's "result" (Moonraker wraps every successful reply in {"result": ...}), or the error.
  core::Result<Json> reply(const core::Result<HttpReply>& res, const std::string& request) const {
    if (!res) {
      if (res.error().code != core::ErrorCode::DeviceUnreachable)
        return core::Error{res.error().code, "the reply to " + request + " was refused: " + res.error().message,
                           name()};
      return core::Error{core::ErrorCode::DeviceUnreachable,
                         "no answer to " + request + " (" + res.error().message +
                             "): check that Moonraker runs, the address and the network",
                         name()};
    }
    const core::Result<Json> body = parseReplyJson(res->body, request, ": is this Moonraker's address?", name());
    if (res->status < 200 || res->status >= 300) {
      std::string message = "HTTP " + std::to_string(res->status);
      if (body && body->is_object() && body->contains("error") && (*body)["error"].is_object() &&
          (*body)["error"].contains("message") && (*body)["error"]["message"].is_string())
        message += ": " + escapeControls((*body)["error"]["message"].get<std::string>());
      return core::Error{core::ErrorCode::DeviceFault, "the printer refused " + request + " (" + message + ")", name()};
    }
    if (!body) return body.error();
    if (body->is_object() && body->contains("result")) return (*body)["result"];
    return body;  // Moonraker before 2021 answered uploads without the wrapper
  }

  core::Status post(const BoundedHttpClient& client, const std::string& path) const {
    const core::Result<Json> answered = reply(client.post(path, "", "", name()), "POST " + path);
    if (!answered) return answered.error();
    return core::Done{};
  }

  core::Status postFile(const BoundedHttpClient& uploader, const std::string& content,
                        const std::string& remoteName) override {
    const std::vector<FormPart> parts = {{"file", content, remoteName, "application/octet-stream"},
                                         {"root", "gcodes", "", ""}};
    const core::Result<Json> answered = reply(uploader.postForm("/server/files/upload", parts, name()),
                                              "POST /server/files/upload (" + remoteName + ")");
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
  return settingsFromUrl<MoonrakerSettings>(url, "moonraker", 80, 7125, "http://192.168.0.20:7125");
}

core::Result<std::unique_ptr<PrinterLink>> makeMoonrakerLink(const MoonrakerSettings& settings,
                                                             const PrinterLinkOptions& options) {
  if (core::Status valid = validateEndpoint(settings.host, settings.port, options); !valid) return valid.error();
  return std::unique_ptr<PrinterLink>(std::make_unique<MoonrakerLink>(settings, options));
}

}  // namespace multidir::hardware
