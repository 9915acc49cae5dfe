#pragma once
// Why core refused an edited plan, as a translated sentence that names the plane and says what to do.
// core::planFromClippingPlanes reports the plane in `where` ("plane K") and the criterion in its English
// message; the sentence is chosen from those, and core's own text stays available as the detail.
#include <QString>

#include "multidir/core/common/result.h"

namespace multidir::ui {

// The plane core names (1-based, in clipping order as core counts them); 0 when it names none.
[[nodiscard]] int refusedPlaneNumber(const core::Error& error);

// "Plane 2 would cut the platform region: move it up or tilt it less." and the like, for a plan of
// `planeCount` planes: the plane is named by its number in printing order (ui/edit/plane_numbering.h), as the
// Edit plan table shows it.
[[nodiscard]] QString refusalText(const core::Error& error, int planeCount);
// The same for an edit of plane `editedPlane` (0-based, clipping order; -1: none, as for a deletion). Core
// cuts the planes in clipping order, the reverse of the printing order the table numbers them in, so moving
// plane 2 can make the cut of plane 1 fail: the sentence then names both ("Plane 2 was not changed: with it
// there, plane 1 is refused. Plane 1 would cut nothing off: ..."), never only the plane the user did not touch.
[[nodiscard]] QString refusalText(const core::Error& error, int planeCount, int editedPlane);

}  // namespace multidir::ui
