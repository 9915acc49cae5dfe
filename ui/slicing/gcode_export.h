#pragma once
// Export G-code: the files of a sliced job copied from the slicing's temporary folder into a folder the user
// picked. Nothing here runs long (a few files), so it runs on the GUI thread.
#include <QCoreApplication>
#include <QString>
#include <QStringList>

namespace multidir::ui {

// The first entry of `folder` (by name) that a MultiDir job does not hold (slicing::inspectJobFolder), or an
// empty string when the folder is missing, empty or holds an earlier job: what to ask about before exporting.
QString otherFileIn(const QString& folder);

// Copies every file of `from` (step-NN.gcode, job.gcode when stitched, the step meshes, print-job.json with
// the estimates) into `to`, creating its parents when missing, the way `multidir slice -o` writes a job: into a
// fresh folder beside `to` (core::StagedFolder), which takes `to`'s place only once every file is copied, so a
// failed export leaves `to` as it was, an earlier job included. An empty folder or an earlier job is replaced as
// a whole; a folder holding other files is refused (nothing written) unless `intoOtherFolder`, when the job's
// files are moved into it, print-job.json last, and the others stay. Returns the names written; on failure
// returns false with a translated message naming the folder or file and the reason.
bool exportSlicedFiles(const QString& from, const QString& to, QStringList* written, QString* error,
                       bool intoOtherFolder = false);

}  // namespace multidir::ui
