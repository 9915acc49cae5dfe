// libFuzzer harness for printer profiles (.ini): loadPrinterProfile must refuse any input clearly
// (tests/support/refusal_promise.h) or load a profile whose numbers a printer can take: a bed of finite
// corners and positive area, a positive finite height and nozzle.
// Build and run: docs/robustness.md ("Fuzzing").
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "fuzz/fuzz_input_file.h"
#include "multidir/slicing/printer_profile.h"
#include "support/refusal_promise.h"

namespace {

std::string brokenProfile(const multidir::slicing::PrinterProfile& profile) {
  if (profile.bedShape.size() < 3) return "loaded a bed with fewer than three corners";
  for (const auto& corner : profile.bedShape)
    if (!corner.allFinite()) return "loaded a bed corner that is not finite";
  if (!(std::isfinite(profile.maxPrintHeightMm) && profile.maxPrintHeightMm > 0)) return "loaded a bad max height";
  if (!(std::isfinite(profile.nozzleDiameterMm) && profile.nozzleDiameterMm > 0)) return "loaded a bad nozzle";
  if (!profile.platformCenter.allFinite() || !profile.park.allFinite() || !std::isfinite(profile.platformZMm))
    return "loaded a platform position that is not finite";
  return {};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = multidir::fuzz::scratchStem() + ".ini";
  multidir::fuzz::writeInput(path, data, size);
  const auto loaded = multidir::slicing::loadPrinterProfile(path);
  std::remove(path.c_str());
  std::string broken = multidir::test::brokenRefusalPromise(loaded, multidir::fuzz::inputText(data, size));
  if (loaded && broken.empty()) broken = brokenProfile(*loaded);
  multidir::fuzz::requirePromise(broken, "loadPrinterProfile");
  return 0;
}
