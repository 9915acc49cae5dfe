#include "ui/common/studio_version.h"

namespace multidir::ui {

QString studioVersion() { return QStringLiteral(MULTIDIR_VERSION); }

}  // namespace multidir::ui
