#pragma once
// Whether two plans cut the same planes in the same order, exactly (every normal and offset bit for bit): what
// "the same plan for any thread count" means for the search's tests.
#include <gtest/gtest.h>

#include <cstddef>
#include <sstream>

#include "multidir/core/search/decompose.h"

namespace multidir::test {

inline ::testing::AssertionResult samePlanes(const core::Decomposition& a, const core::Decomposition& b) {
  if (a.clippingPlanes.size() != b.clippingPlanes.size())
    return ::testing::AssertionFailure() << a.clippingPlanes.size() << " planes against " << b.clippingPlanes.size();
  for (std::size_t k = 0; k < a.clippingPlanes.size(); ++k) {
    const core::Plane& p = a.clippingPlanes[k];
    const core::Plane& q = b.clippingPlanes[k];
    if (p.normal != q.normal || p.offset != q.offset) {
      std::ostringstream text;
      text.precision(17);
      text << "plane " << k << ": normal (" << p.normal.transpose() << "), offset " << p.offset << " against ("
           << q.normal.transpose() << "), offset " << q.offset;
      return ::testing::AssertionFailure() << text.str();
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace multidir::test
