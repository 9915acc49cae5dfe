#pragma once
// The Hardware panel against the device simulator on 127.0.0.1 (ephemeral port), with the hardware tests'
// short timeouts: buttons pressed as an operator would, outcomes read from the panel's labels and the
// simulator's own state. Every wait has a deadline (kWaitMs).
#include <gtest/gtest.h>

#include <QColor>
#include <QDoubleSpinBox>
#include <QImage>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTest>
#include <chrono>
#include <cmath>
#include <vector>

#include "hardware/hardware_test_support.h"
#include "multidir/core/common/units.h"
#include "multidir/core/search/decomposition.h"
#include "multidir/hardware/device_simulator.h"
#include "ui/device/connection_form.h"
#include "ui/device/device_link.h"
#include "ui/device/hardware_panel.h"
#include "ui/device/print_run_driver.h"
#include "ui/document/studio_document.h"

namespace multidir::ui {

inline constexpr int kWaitMs = 5000;  // generous: the simulator answers within milliseconds

// The hardware tests' short timeouts and intervals, with the rotary platform's unit id.
inline hardware::ConnectionSettings fastSettings(int port) { return hardware::test::fastSettings(port, 1); }

inline QString degreesText(double value) { return QLocale().toString(value, 'f', 2) + QStringLiteral("°"); }

// Pixels of `image` within a small distance of `color`.
inline int pixelsNear(const QImage& image, const QColor& color) {
  int count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      if (std::abs(c.red() - color.red()) + std::abs(c.green() - color.green()) + std::abs(c.blue() - color.blue()) < 30)
        ++count;
    }
  return count;
}

// A 4-DOF plan with one region per angle (degrees about the platform's axis, in printing order).
inline core::Decomposition planWithAngles(const std::vector<double>& anglesDegrees) {
  core::Decomposition plan;
  for (double angle : anglesDegrees) {
    core::Region region;
    region.angles.rotaryDegrees = angle;
    region.printingDirection = core::Vec3(0.0, -std::sin(core::degToRad(angle)), std::cos(core::degToRad(angle)));
    plan.regions.push_back(region);
  }
  return plan;
}

class HardwarePanelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(sim.start().ok());
    core::MachineSpec profile;
    profile.kind = core::MachineKind::RotaryPlatform;
    profile.minAngleDegrees = -60.0;
    profile.maxAngleDegrees = 60.0;
    profile.angleStepDegrees = 1.0;
    document.setMachine(profile);
    panel.connectionForm()->setKind(DeviceKind::RotaryPlatform);
    panel.connectionForm()->setSettings(fastSettings(sim.port()));
    panel.connectionForm()->setRotarySpeedDegreesPerSecond(60.0);
    hardware::PrintRunOptions runOptions;
    runOptions.settleTime = std::chrono::milliseconds(50);
    panel.setPrintRunOptions(runOptions);
    panel.resize(480, 1000);
    panel.show();
  }

  QPushButton* buttonNamed(const char* name) {
    auto* found = panel.findChild<QPushButton*>(QString::fromLatin1(name));
    EXPECT_NE(found, nullptr) << name;
    return found;
  }
  // Presses a button as the operator would: only an enabled button does anything.
  void press(const char* name) {
    QPushButton* target = buttonNamed(name);
    ASSERT_NE(target, nullptr);
    ASSERT_TRUE(target->isEnabled()) << name << " is disabled; message: " << panel.messageText().toStdString();
    QTest::mouseClick(target, Qt::LeftButton);
  }
  QString label(const char* name) {
    auto* found = panel.findChild<QLabel*>(QString::fromLatin1(name));
    return found ? found->text() : QStringLiteral("<no label %1>").arg(QString::fromLatin1(name));
  }
  const DeviceSnapshot& snapshot() { return panel.deviceLink()->snapshot(); }

  void connectPanel() {
    press("connectButton");
    ASSERT_TRUE(QTest::qWaitFor([&] { return snapshot().state == DeviceState::Connected; }, kWaitMs))
        << panel.messageText().toStdString();
    EXPECT_EQ(label("stateValue"), QStringLiteral("Connected"));
  }
  void enableAndHome() {
    press("enableButton");
    ASSERT_TRUE(QTest::qWaitFor([&] { return snapshot().enabled; }, kWaitMs)) << panel.messageText().toStdString();
    press("homeButton");
    ASSERT_TRUE(QTest::qWaitFor([&] { return snapshot().homed && !snapshot().homing; }, kWaitMs))
        << panel.messageText().toStdString();
    EXPECT_EQ(label("homedValue"), QStringLiteral("yes"));
  }
  void goTo(double angleDegrees) {
    panel.findChild<QDoubleSpinBox*>(QStringLiteral("targetAngle"))->setValue(angleDegrees);
    press("goToButton");
  }

  // The plan shown (the document's): what the panel runs.
  void givePlan(core::Decomposition plan) {
    SearchRun run;
    run.plan = std::make_shared<const core::Decomposition>(std::move(plan));
    document.setPlan(run);
  }

  hardware::DeviceSimulator sim;
  StudioDocument document;
  HardwarePanel panel{&document};
};

}  // namespace multidir::ui
