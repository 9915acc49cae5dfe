#pragma once
// Where each kind of file dialog starts: the folder last used for that kind of file (a model is looked for
// where models were opened from, a project where projects were saved), kept in QSettings across sessions.
// MainWindow::dialogFolder falls back to the project's or the model's folder when a kind was never used.
#include <QString>

namespace multidir::ui {

enum class FileKind { Model, Project, Plan, MachineProfile, Picture };

// The folder last used for `kind`; empty when none was (or it has gone).
[[nodiscard]] QString rememberedDialogFolder(FileKind kind);
// Remembers the folder of `path` for `kind`: the folder itself when `path` is one, else the file's folder.
void rememberDialogFolder(FileKind kind, const QString& path);

}  // namespace multidir::ui
