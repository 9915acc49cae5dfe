// Export G-code writes a job folder the way `multidir slice -o` does: swapped in once complete (an earlier
// job replaced as a whole), a folder holding other files refused unless allowed.
#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include "ui/slicing/gcode_export.h"

namespace multidir::ui {
namespace {

void writeFile(const QString& path, const QByteArray& text) {
  QFile file(path);
  ASSERT_TRUE(file.open(QIODevice::WriteOnly));
  file.write(text);
}

QByteArray readFile(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// A sliced one-step job, as the slicing's temporary folder holds it.
QString slicedJob(const QTemporaryDir& scratch) {
  const QString from = scratch.filePath(QStringLiteral("sliced"));
  QDir().mkpath(from);
  writeFile(from + QStringLiteral("/print-job.json"), R"({"schema": "multidir-print-job", "slicing": {}})");
  writeFile(from + QStringLiteral("/step-01.gcode"), "; the new job\n");
  return from;
}

QStringList entriesOf(const QString& folder) {
  return QDir(folder).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
}

}  // namespace

TEST(GcodeExport, AnEarlierLongerJobIsReplacedAsAWhole) {
  QTemporaryDir scratch;
  ASSERT_TRUE(scratch.isValid());
  const QString to = scratch.filePath(QStringLiteral("exported"));
  QDir().mkpath(to);
  writeFile(to + QStringLiteral("/print-job.json"), R"({"schema": "multidir-print-job"})");
  writeFile(to + QStringLiteral("/step-01.gcode"), "; the earlier job\n");
  writeFile(to + QStringLiteral("/step-02.gcode"), "; the earlier job\n");
  QString error;
  ASSERT_TRUE(exportSlicedFiles(slicedJob(scratch), to, nullptr, &error)) << error.toStdString();
  EXPECT_EQ(entriesOf(to), (QStringList{QStringLiteral("print-job.json"), QStringLiteral("step-01.gcode")}));
  EXPECT_EQ(readFile(to + QStringLiteral("/step-01.gcode")), QByteArray("; the new job\n"));
  EXPECT_EQ(entriesOf(scratch.path()), (QStringList{QStringLiteral("exported"), QStringLiteral("sliced")}));
}

TEST(GcodeExport, AFolderHoldingOtherFilesIsRefusedNamingOneAndLeftAlone) {
  QTemporaryDir scratch;
  ASSERT_TRUE(scratch.isValid());
  const QString to = scratch.filePath(QStringLiteral("mine"));
  QDir().mkpath(to);
  writeFile(to + QStringLiteral("/notes.txt"), "the user's\n");
  QString error;
  EXPECT_FALSE(exportSlicedFiles(slicedJob(scratch), to, nullptr, &error));
  EXPECT_TRUE(error.contains(QStringLiteral("notes.txt"))) << error.toStdString();
  EXPECT_EQ(otherFileIn(to), QStringLiteral("notes.txt"));
  EXPECT_EQ(entriesOf(to), QStringList{QStringLiteral("notes.txt")});
}

TEST(GcodeExport, WritingIntoAFolderHoldingOtherFilesWhenAllowedKeepsThem) {
  QTemporaryDir scratch;
  ASSERT_TRUE(scratch.isValid());
  const QString to = scratch.filePath(QStringLiteral("mine"));
  QDir().mkpath(to);
  writeFile(to + QStringLiteral("/notes.txt"), "the user's\n");
  QString error;
  ASSERT_TRUE(exportSlicedFiles(slicedJob(scratch), to, nullptr, &error, true)) << error.toStdString();
  EXPECT_EQ(entriesOf(to), (QStringList{QStringLiteral("notes.txt"), QStringLiteral("print-job.json"),
                                        QStringLiteral("step-01.gcode")}));
  EXPECT_EQ(readFile(to + QStringLiteral("/notes.txt")), QByteArray("the user's\n"));
}

}  // namespace multidir::ui
