#pragma once
// MultiDir's version as the studio states it (About box, project and plan files).
#include <QString>

namespace multidir::ui {

// MultiDir's version ("0.1.0"), from the CMake project.
QString studioVersion();

}  // namespace multidir::ui
