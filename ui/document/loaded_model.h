#pragma once
// A model the studio shows: the mesh, shared read-only between the GUI and worker threads, plus what the
// status bar says about it.
#include <QMetaType>
#include <QString>
#include <memory>
#include <optional>

#include "multidir/core/mesh/mesh_io.h"

namespace multidir::ui {

struct LoadedModel {
  QString name;        // for the window title and status bar: "kitten.off", or a sample's title
  QString sourcePath;  // the file it came from; empty for a sample
  QString checksum;    // core::fileChecksum of that file as it was read; empty for a sample
  QString sampleId;    // the core::samples id of a sample; empty for a file
  std::shared_ptr<const core::TriangleMesh> mesh;  // never null in a delivered model
  core::MeshStatistics statistics;
  std::optional<core::Vec3> naturalUp;  // the up direction the model was made with, when known (samples)
  QStringList repairs;  // what loading repaired, one sentence each
};

}  // namespace multidir::ui

Q_DECLARE_METATYPE(multidir::ui::LoadedModel)
