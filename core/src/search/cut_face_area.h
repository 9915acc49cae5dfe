#pragma once
// The cut faces of a search node's plan, for the apart machine's price of a part (docs/apart.md, "The price of
// a part"). Internal to core.
#include "search/search_node.h"

namespace multidir::core::detail {

// The area (mm^2) of the cut faces of every region cut off along the node's chain: each region's cap on the
// plane that cut it, one side of each cut (the face below it is as large).
double cutFaceAreaMm2(const SearchNode& node);

}  // namespace multidir::core::detail
