#pragma once
// Small pose searches for the tests: a few normals and beams keep each pose's search to a fraction of a second.
#include "multidir/core/search/pose_search.h"
#include "support/up_y_machine.h"

namespace multidir::test {

// proxyFaces: SearchOptions' default unless given.
inline core::SearchOptions smallSearchOptions(int threads = 1, int proxyFaces = core::SearchOptions().proxyFaces) {
  core::SearchOptions options;
  options.beamWidth = 2;
  options.candidates.normalSamples = 40;
  options.refinementRounds = 0;
  options.threads = threads;
  options.proxyFaces = proxyFaces;
  return options;
}

inline core::PoseOptions fewPoses(int poses = 6, int searches = 2) {
  core::PoseOptions options;
  options.poses = poses;
  options.fullSearches = searches;
  return options;
}

}  // namespace multidir::test
