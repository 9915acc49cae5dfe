#include "multidir/hardware/modbus_library.h"

#include <modbus.h>

namespace multidir::hardware {

std::string modbusLibraryVersion() {
  return std::to_string(libmodbus_version_major) + "." + std::to_string(libmodbus_version_minor) + "." +
         std::to_string(libmodbus_version_micro);
}

}  // namespace multidir::hardware
