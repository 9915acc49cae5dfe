// Languages: --lang picks the translations embedded in the studio; menus and panels follow.
#include <gtest/gtest.h>

#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>

#include "ui/main_window.h"
#include "ui/studio_startup.h"

namespace multidir::ui {
namespace {

QStringList menuTitles(const MainWindow& window) {
  QStringList titles;
  for (const QAction* action : window.menuBar()->actions()) titles << action->text();
  return titles;
}

// Starts the studio's way (command line, then translations) and restores English afterwards.
class StudioLanguage : public ::testing::Test {
 protected:
  void TearDown() override { installTranslations(QStringLiteral("en")); }

  static void startWith(const QString& language) {
    const StudioCommandLine commandLine =
        parseStudioCommandLine({QStringLiteral("multidir-studio"), QStringLiteral("--lang"), language});
    ASSERT_FALSE(commandLine.exitNow) << commandLine.text.toStdString();
    EXPECT_EQ(commandLine.options.language, language);
    ASSERT_TRUE(installTranslations(chooseLanguage(commandLine.options.language)));
  }
};

TEST_F(StudioLanguage, GermanMenusAndButtons) {
  startWith(QStringLiteral("de"));
  MainWindow window;
  const QStringList titles = menuTitles(window);
  EXPECT_TRUE(titles.contains(QStringLiteral("&Datei"))) << titles.join(QLatin1Char(',')).toStdString();
  EXPECT_TRUE(titles.contains(QStringLiteral("&Ansicht")));
  EXPECT_EQ(window.findChild<QPushButton*>(QStringLiteral("runSearch"))->text(), QStringLiteral("Suche &starten"));
}

TEST_F(StudioLanguage, SimplifiedChineseMenusAndButtons) {
  startWith(QStringLiteral("zh_CN"));
  MainWindow window;
  const QStringList titles = menuTitles(window);
  EXPECT_TRUE(titles.contains(QStringLiteral("文件(&F)"))) << titles.join(QLatin1Char(',')).toStdString();
  EXPECT_TRUE(titles.contains(QStringLiteral("视图(&V)")));
  EXPECT_EQ(window.findChild<QPushButton*>(QStringLiteral("runSearch"))->text(), QStringLiteral("运行搜索(&R)"));
}

// The Hardware panel is translated too: its dock, its buttons, and the state shown before any connection.
TEST_F(StudioLanguage, GermanHardwarePanel) {
  startWith(QStringLiteral("de"));
  MainWindow window;
  QWidget* panel = window.findChild<QWidget*>(QStringLiteral("hardwarePanel"));
  ASSERT_NE(panel, nullptr);
  EXPECT_EQ(panel->findChild<QPushButton*>(QStringLiteral("connectButton"))->text(), QStringLiteral("Verbinden"));
  EXPECT_EQ(panel->findChild<QPushButton*>(QStringLiteral("estopButton"))->text(), QStringLiteral("NOT-HALT"));
  EXPECT_EQ(panel->findChild<QPushButton*>(QStringLiteral("startRunButton"))->text(), QStringLiteral("Lauf starten"));
  EXPECT_EQ(panel->findChild<QLabel*>(QStringLiteral("stateValue"))->text(), QStringLiteral("Getrennt"));
}

TEST_F(StudioLanguage, SimplifiedChineseHardwareDockAndButtons) {
  startWith(QStringLiteral("zh_CN"));
  MainWindow window;
  const auto* dock = window.findChild<QDockWidget*>(QStringLiteral("hardwareDock"));
  ASSERT_NE(dock, nullptr);
  EXPECT_EQ(dock->windowTitle(), QStringLiteral("硬件"));
  EXPECT_EQ(dock->findChild<QPushButton*>(QStringLiteral("connectButton"))->text(), QStringLiteral("连接"));
  EXPECT_EQ(dock->findChild<QPushButton*>(QStringLiteral("estopButton"))->text(), QStringLiteral("急停"));
}

TEST_F(StudioLanguage, EnglishInstallsNoTranslation) {
  startWith(QStringLiteral("en"));
  MainWindow window;
  EXPECT_TRUE(menuTitles(window).contains(QStringLiteral("&File")));
}

TEST(StudioLanguageOption, UnknownLanguageIsAUsageError) {
  const StudioCommandLine commandLine =
      parseStudioCommandLine({QStringLiteral("multidir-studio"), QStringLiteral("--lang"), QStringLiteral("fr")});
  EXPECT_TRUE(commandLine.exitNow);
  EXPECT_EQ(commandLine.exitCode, 2);
  EXPECT_TRUE(commandLine.text.contains(QStringLiteral("fr")));
}

TEST(StudioLanguageOption, ExplicitLanguageWinsOverTheSystemLocale) {
  EXPECT_EQ(chooseLanguage(QStringLiteral("zh_CN")), QStringLiteral("zh_CN"));
  EXPECT_EQ(chooseLanguage(QStringLiteral("en")), QStringLiteral("en"));
  EXPECT_TRUE(QStringList({QStringLiteral("en"), QStringLiteral("de"), QStringLiteral("zh_CN")})
                  .contains(chooseLanguage(QString())));
}

}  // namespace
}  // namespace multidir::ui
