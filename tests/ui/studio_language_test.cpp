// Languages: --lang picks the translations embedded in the studio; menus and panels follow.
#include <gtest/gtest.h>

#include <QAction>
#include <QDockWidget>
#include <QHash>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QStatusBar>

#include "ui/main_window.h"
#include "ui/panels/overhang_panel.h"
#include "ui/studio_startup.h"
#include "ui/studio_test_support.h"

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

// Qt's own texts (standard buttons of message boxes, file dialogs) follow the language too.
TEST_F(StudioLanguage, QtsOwnButtonsAreGermanAndChineseToo) {
  startWith(QStringLiteral("de"));
  {
    QMessageBox box(QMessageBox::Warning, QString(), QString(), QMessageBox::Save | QMessageBox::Cancel);
    EXPECT_EQ(box.button(QMessageBox::Cancel)->text(), QStringLiteral("Abbrechen"));
    EXPECT_EQ(box.button(QMessageBox::Save)->text(), QStringLiteral("Speichern"));
  }
  startWith(QStringLiteral("zh_CN"));
  QMessageBox box(QMessageBox::Warning, QString(), QString(), QMessageBox::Cancel);
  EXPECT_EQ(box.button(QMessageBox::Cancel)->text(), QStringLiteral("取消"));
}

TEST_F(StudioLanguage, GermanNumbersUseTheDecimalCommaAndThePointBetweenThousands) {
  startWith(QStringLiteral("de"));
  MainWindow window;
  ASSERT_NO_FATAL_FAILURE(test::openSample(window, QStringLiteral("snowman")));
  const QString area = window.overhangPanel()->riskyAreaText();
  EXPECT_TRUE(QRegularExpression(QStringLiteral("^\\d{1,3}(\\.\\d{3})*,\\d mm²$")).match(area).hasMatch())
      << area.toStdString();
}

// Alt+letter reaches one entry per menu: no two entries of a menu (or two menus) share a mnemonic.
TEST_F(StudioLanguage, EnglishMenusHaveNoMnemonicTwice) {
  startWith(QStringLiteral("en"));
  MainWindow window;
  auto collisions = [](const QList<QAction*>& actions) {
    QStringList found;
    QHash<QChar, QString> taken;
    static const QRegularExpression mnemonic(QStringLiteral("&([^&])"));
    for (const QAction* action : actions) {
      const QRegularExpressionMatch match = mnemonic.match(action->text());
      if (!match.hasMatch()) continue;
      const QChar key = match.captured(1).front().toLower();
      if (taken.contains(key)) found << taken.value(key) + QStringLiteral(" / ") + action->text();
      taken.insert(key, action->text());
    }
    return found;
  };
  QStringList all = collisions(window.menuBar()->actions());
  for (const QMenu* menu : window.menuBar()->findChildren<QMenu*>()) all << collisions(menu->actions());
  EXPECT_TRUE(all.isEmpty()) << all.join(QStringLiteral("; ")).toStdString();
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
