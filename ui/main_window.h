#pragma once
// MultiDir Studio's main window: a 3D view of one model, the File menu (open, samples, quit), the up
// direction it is printed along, and a status bar with the model's size, volume and risky overhang area.
//
// Loading runs off the GUI thread (ModelLoader); the window stays responsive and shows a busy indicator.
// A failed load keeps the current model and reports the error in the status bar, in a non-modal message
// box and through loadFailed().
#include <QMainWindow>
#include <QString>
#include <cstddef>
#include <optional>

#include "ui/loaded_model.h"

class QComboBox;
class QLabel;
class QMenu;
class QProgressBar;

namespace multidir::ui {

class MeshViewerWidget;
class ModelLoader;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;
  MainWindow(const MainWindow&) = delete;
  MainWindow& operator=(const MainWindow&) = delete;

  // Starts loading a mesh file (.stl .obj .off .ply); the up direction stays as it is.
  void openFile(const QString& path);
  // Starts building a sample (a core::samples id); the up direction becomes the sample's (+Z).
  void openSample(const QString& id);

  // The printing (up) direction; a zero or non-finite vector is ignored. Axis directions select the
  // matching entry of the Up box; any other direction adds a "custom" entry.
  void setUpDirection(const core::Vec3& up);
  [[nodiscard]] core::Vec3 upDirection() const;

  [[nodiscard]] bool isLoading() const;
  [[nodiscard]] bool hasModel() const { return m_model.has_value(); }
  // The model shown (nullopt before the first successful load).
  [[nodiscard]] const std::optional<LoadedModel>& model() const { return m_model; }
  [[nodiscard]] MeshViewerWidget* viewer() const { return m_viewer; }

 signals:
  // A model was loaded and is now shown.
  void modelShown(const QString& name);
  // Loading failed; the previous model (if any) is still shown. `message` is what the status bar says:
  // the file and a translated sentence on the problem (core's detail is in the message box).
  void loadFailed(const QString& message);
  void loadingChanged(bool loading);

 private:
  void buildMenus();
  void buildUpBox();
  void buildStatusBar();
  void chooseFile();
  void showModel(const LoadedModel& model);
  void reportLoadError(const QString& source, const QString& headline, const QString& detail);
  void onUpChanged();
  void updateModelStatus();
  void setBusy(bool busy);

  MeshViewerWidget* m_viewer = nullptr;
  ModelLoader* m_loader = nullptr;
  QComboBox* m_upBox = nullptr;
  QLabel* m_fileLabel = nullptr;
  QLabel* m_trianglesLabel = nullptr;
  QLabel* m_volumeLabel = nullptr;
  QLabel* m_riskyLabel = nullptr;
  QLabel* m_busyLabel = nullptr;
  QProgressBar* m_busyBar = nullptr;
  QString m_lastDirectory;
  QString m_pendingName;
  std::optional<LoadedModel> m_model;
};

}  // namespace multidir::ui
