#pragma once
// Loads models off the GUI thread. Each request runs core::loadMesh (or builds a sample) on its own
// QThread; the result comes back to the GUI thread as a value through a queued signal.
//
// Thread: create and call from the GUI thread; the signals are emitted there too.
#include <QObject>
#include <QString>
#include <cstdint>
#include <vector>

#include "ui/document/loaded_model.h"

class QThread;

namespace multidir::ui {

class ModelLoader : public QObject {
  Q_OBJECT

 public:
  explicit ModelLoader(QObject* parent = nullptr);
  // Waits for loads still running (their results are dropped).
  ~ModelLoader() override;
  ModelLoader(const ModelLoader&) = delete;
  ModelLoader& operator=(const ModelLoader&) = delete;

  // Starts loading a mesh file. A request supersedes any earlier one still running: only the latest
  // request's outcome is reported.
  void loadFile(const QString& path);
  // Starts building the sample with the given core::samples id.
  void loadSample(const QString& id);

  [[nodiscard]] bool isBusy() const { return m_busy; }

 signals:
  void loaded(const multidir::ui::LoadedModel& model);
  // `source` is the file name or sample id; `headline` is a translated sentence on what went wrong and
  // what to do, `detail` core's own description (which faces, how many, where).
  void failed(const QString& source, const QString& headline, const QString& detail);
  void busyChanged(bool busy);

 private:
  struct Outcome;
  template <typename Work>
  void start(const QString& source, Work work);
  void setBusy(bool busy);

  std::uint64_t m_latest = 0;
  bool m_busy = false;
  std::vector<QThread*> m_running;
};

}  // namespace multidir::ui
