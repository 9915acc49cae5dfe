#pragma once
// One numbering of clipping planes everywhere in the studio: printing order, like the regions. Plane k
// (1-based) is the base of region k + 1, the k-th plane the machine prints on; region 1 stands on the
// platform. A plan keeps its planes in clipping order (core::Decomposition: plane i, 0-based, cut region
// N - i off), so plane i of N carries the number N - i.
namespace multidir::ui {

// The number shown for plane `index` (0-based, clipping order) of `count` planes.
[[nodiscard]] constexpr int planeNumber(int index, int count) { return count - index; }
// The plane (0-based, clipping order) shown as `number` among `count` planes.
[[nodiscard]] constexpr int planeIndexOfNumber(int number, int count) { return count - number; }

}  // namespace multidir::ui
