#include "ui/jobs/model_loader.h"

#include <QFile>
#include <QFileInfo>
#include <QThread>
#include <algorithm>
#include <exception>
#include <memory>
#include <new>
#include <optional>

#include "multidir/core/plan/checksum.h"
#include "multidir/core/samples/samples.h"
#include "ui/common/error_text.h"

namespace multidir::ui {

struct ModelLoader::Outcome {
  std::optional<LoadedModel> model;
  QString headline;  // set when model is empty
  QString detail;

  void fail(const core::Error& error) {
    headline = errorHeadline(error.code);
    detail = QString::fromStdString(error.describe());
  }
};

ModelLoader::ModelLoader(QObject* parent) : QObject(parent) {
  static const int registered = qRegisterMetaType<multidir::ui::LoadedModel>();
  (void)registered;
}

ModelLoader::~ModelLoader() {
  for (QThread* thread : m_running) {
    thread->wait();
    delete thread;
  }
}

template <typename Work>
void ModelLoader::start(const QString& source, Work work) {
  const std::uint64_t request = ++m_latest;
  auto outcome = std::make_shared<Outcome>();
  QThread* thread = QThread::create([outcome, work = std::move(work)]() mutable {
    // Nothing may escape a worker thread: whatever goes wrong becomes a message.
    try {
      work(*outcome);
    } catch (const std::bad_alloc&) {
      outcome->model.reset();
      outcome->headline = tr("Not enough memory to load this model.");
    } catch (const std::exception& e) {
      outcome->model.reset();
      outcome->headline = tr("Unexpected error while loading.");
      outcome->detail = QString::fromLocal8Bit(e.what());
    } catch (...) {
      outcome->model.reset();
      outcome->headline = tr("Unexpected error while loading.");
    }
  });
  m_running.push_back(thread);
  // QThread::finished comes from the worker; with `this` as context it is queued to the GUI thread.
  connect(thread, &QThread::finished, this, [this, thread, outcome, request, source] {
    m_running.erase(std::remove(m_running.begin(), m_running.end(), thread), m_running.end());
    thread->deleteLater();
    if (request != m_latest) return;  // superseded by a later request
    setBusy(false);
    if (outcome->model) {
      emit loaded(*outcome->model);
    } else {
      emit failed(source, outcome->headline, outcome->detail);
    }
  });
  setBusy(true);
  thread->start();
}

void ModelLoader::loadFile(const QString& path) {
  start(QFileInfo(path).fileName(), [path](Outcome& out) {
    core::Result<core::LoadedMesh> result = core::loadMesh(QFile::encodeName(path).toStdString());
    if (!result) {
      out.fail(result.error());
      return;
    }
    LoadedModel model;
    model.name = QFileInfo(path).fileName();
    model.sourcePath = path;
    // Read again for the checksum: a project remembers which bytes its plan was made on.
    const core::Result<std::string> checksum = core::fileChecksum(QFile::encodeName(path).toStdString());
    if (checksum) model.checksum = QString::fromStdString(checksum.value());
    model.statistics = result->report.statistics;
    for (const std::string& repair : result->report.repairs) model.repairs << QString::fromStdString(repair);
    model.mesh = std::make_shared<const core::TriangleMesh>(std::move(result.value().mesh));
    out.model = std::move(model);
  });
}

void ModelLoader::loadSample(const QString& id) {
  start(id, [id](Outcome& out) {
    const std::string key = id.toStdString();
    core::Result<core::TriangleMesh> result = core::samples::makeSample(key);
    if (!result) {
      out.fail(result.error());
      return;
    }
    LoadedModel model;
    model.name = id;
    model.sampleId = id;
    for (const core::samples::SampleInfo& info : core::samples::catalogue()) {
      if (info.id == key) model.name = QString::fromStdString(info.title);
    }
    model.statistics = core::computeStatistics(result.value());
    model.naturalUp = core::samples::sampleUp();
    model.mesh = std::make_shared<const core::TriangleMesh>(std::move(result.value()));
    out.model = std::move(model);
  });
}

void ModelLoader::setBusy(bool busy) {
  if (busy == m_busy) return;
  m_busy = busy;
  emit busyChanged(busy);
}

}  // namespace multidir::ui
