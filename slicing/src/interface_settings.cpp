#include "multidir/slicing/interface_settings.h"

namespace multidir::slicing {

std::vector<std::pair<std::string, std::string>> interfaceSettings() {
  return {
      // The base plane lies on the lower step's top skin: a bottom skin over it would be a second solid slab
      // inside the part. Overhangs of the step over air still get perimeters (and bridges where PrusaSlicer
      // detects them over sparse infill); the plan keeps them within the printable angle or supported.
      {"bottom_solid_layers", "0"},
      {"bottom_solid_min_thickness", "0"},
      // Printed onto plastic, not onto the bed: the normal width and speeds.
      {"first_layer_extrusion_width", "0"},
      {"first_layer_speed", "100%"},
  };
}

}  // namespace multidir::slicing
