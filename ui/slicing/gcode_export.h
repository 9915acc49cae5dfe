#pragma once
// Export G-code: the files of a sliced job copied from the slicing's temporary folder into a folder the user
// picked. Nothing here runs long (a few files), so it runs on the GUI thread.
#include <QCoreApplication>
#include <QString>
#include <QStringList>

namespace multidir::ui {

// Copies every file of `from` (step-NN.gcode, job.gcode when stitched, the step meshes, print-job.json with
// the estimates) into `to`, creating it with its parents when missing. Each file is written beside its
// target and renamed into place, print-job.json last, so a folder whose print-job.json is new holds the
// whole job. Returns the names written; on failure returns false with a translated message naming the folder
// or file and the reason (earlier files of this export stay; the old print-job.json, if any, is removed
// first so it never describes a half-written job).
bool exportSlicedFiles(const QString& from, const QString& to, QStringList* written, QString* error);

}  // namespace multidir::ui
