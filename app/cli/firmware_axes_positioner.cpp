#include "firmware_axes_positioner.h"

namespace multidir::cli {
namespace {

class FirmwareAxesPositioner : public hardware::Positioner {
 public:
  explicit FirmwareAxesPositioner(const hardware::PrinterLink& printer) : m_printer(printer) {}

  core::Status startMove(const hardware::PlatformOrientation& target) override {
    if (target.kind != hardware::PlatformOrientation::Kind::Rotary || target.rotaryDegrees != 0.0)
      return core::Error{core::ErrorCode::InvalidParameter,
                         "the printer's program turns the platform itself: only its rest position can be asked for",
                         name()};
    if (m_stopLatched)
      return core::Error{core::ErrorCode::InvalidParameter, "a stop is latched: clear it first", name()};
    m_targetSet = true;
    return core::Done{};
  }
  core::Status stopMotion() override {
    m_stopLatched = true;
    return core::Done{};
  }
  core::Status emergencyStop() override {
    m_stopLatched = true;
    return core::Done{};
  }
  core::Status clearStop() override {
    m_stopLatched = false;
    return core::Done{};
  }
  [[nodiscard]] hardware::PositionerSnapshot snapshot() const override {
    hardware::PositionerSnapshot s;
    const hardware::PrinterStatus printer = m_printer.status();
    s.linkUp = !printer.linkLost;
    s.reached = m_targetSet && s.linkUp;
    s.problem = s.linkUp ? std::string() : "the printer, whose axes turn the platform, does not answer";
    s.stopLatched = m_stopLatched;
    s.stopConfirmed = m_stopLatched;
    return s;
  }
  [[nodiscard]] std::string name() const override { return "the platform on the printer's own axes"; }

 private:
  const hardware::PrinterLink& m_printer;
  bool m_targetSet = false;
  bool m_stopLatched = false;
};

}  // namespace

std::unique_ptr<hardware::Positioner> makeFirmwareAxesPositioner(const hardware::PrinterLink& printer) {
  return std::make_unique<FirmwareAxesPositioner>(printer);
}

}  // namespace multidir::cli
