// The scaling run (issue 17): `multidir decompose` end to end (load, search, cuts, supports, save) on the shared
// models subdivided 4^K times, and on a model of about a million faces, each in its own process so that its
// peak memory is its own:
//
//   multidir_scaling_bench [--models kitten,bunny,fertility] [--levels 0,1,2,3] [--million] [--full]
//                          [--noise MM] [--keep DIR] [--repeat R] [--normals N1,N2,...]
//                          [--machine 5dof|4dof] [--axes N] [--pose auto] [--finalists on|off]
//
// --levels: subdivision levels (0: the model as shared; 3: 64x the faces).
// --million: also the knight subdivided 5 times (1,024,000 faces), smooth and with --noise (default 0.02 mm)
//   along the normals, like a scan's measurement noise (then no face of the proxy comes for free).
// --full: every run also with --no-proxy (the full mesh searched; slow: minutes at 64x).
// --repeat R: every run R times; wall and search seconds are the medians (this machine's speed drifts by 10-20 %
//   between runs, so the "x of 1x" ratio of single runs is as noisy as that).
// --normals N1,N2,...: every run once per candidate-normal count (`--normals` of the CLI; default: the CLI's).
//   The search's plan moves by tens of percent with changes smaller than its candidate spacing (docs/search.md),
//   so comparing the proxy with the full search on one draw compares two draws of that spread; with several
//   counts a summary at the end gives each model's and mode's median J_G after / before over the draws.
// --machine 4dof --axes N: every run a 4-DOF search over N rotation axes (`--machine 4dof --axis-search N`).
// --pose auto: every run a pose search (`--pose auto`).
// --finalists on|off: every run with `--polish-finalists` or `--no-polish-finalists` (default: the CLI's).
// Columns: faces, the proxy's faces (0: none), wall seconds of the whole command, its CPU seconds (user and
// system, all threads: what the machine's load changes least), the search's seconds, peak
// resident MiB (getrusage of the child), regions, J_G after / before, and the wall time over the same model's
// at level 0 in the same mode. The models are written to a temporary folder (or --keep DIR) as binary STL.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "multidir/core/mesh/mesh_io.h"
#include "multidir/core/mesh/mesh_resolution.h"
#include "noisy_surface.h"
#include "bench_support.h"
#include "shared_model_path.h"

using namespace multidir::core;
namespace fs = std::filesystem;

using multidir::bench::commaList;

namespace {

struct Case {
  std::string name;  // "kitten 16x"
  std::string model;
  int level = 0;
  double noiseMm = 0.0;
  std::string file;
};

struct Outcome {
  bool ok = false;
  double wallSeconds = 0, cpuSeconds = 0, searchSeconds = 0, peakMiB = 0, jgBefore = 0, jgAfter = 0;
  long long faces = 0, proxyFaces = 0, regions = 0;
  std::string error;
};

bool writeCase(Case& c, const fs::path& folder) {
  c.file = (folder / (c.model + "-" + std::to_string(c.level) + (c.noiseMm > 0 ? "-noisy" : "") + ".stl")).string();
  if (fs::exists(c.file)) return true;
  const auto loaded = loadMesh(multidir::bench::sharedModelPath(c.model));
  if (!loaded.ok()) {
    std::fprintf(stderr, "%s: %s\n", c.model.c_str(), loaded.error().describe().c_str());
    return false;
  }
  auto fine = subdivided(loaded->mesh, c.level);
  if (!fine.ok()) {
    std::fprintf(stderr, "%s: %s\n", c.model.c_str(), fine.error().describe().c_str());
    return false;
  }
  if (c.noiseMm > 0) multidir::bench::addNoise(*fine, c.noiseMm);
  if (const Status saved = saveMesh(*fine, c.file); !saved.ok()) {
    std::fprintf(stderr, "%s: %s\n", c.file.c_str(), saved.error().describe().c_str());
    return false;
  }
  return true;
}

// How every run searches, beyond the CLI's defaults.
struct SearchMode {
  std::string machine;  // empty: the CLI's default (5-DOF)
  int axes = 0;         // 4-DOF axis search over this many axes
  bool autoPose = false;
  std::string finalists;  // "on", "off", or empty: the CLI's default
};

Outcome run(const Case& c, bool full, int normals, const SearchMode& mode, const fs::path& folder) {
  Outcome out;
  const fs::path plan = folder / ("plan-" + fs::path(c.file).stem().string() + (full ? "-full" : ""));
  const fs::path summary = plan.string() + ".json";
  std::vector<std::string> args{MULTIDIR_CLI, "decompose", c.file, "--up", "y", "-o", plan.string(), "--summary",
                                summary.string()};
  if (full) args.emplace_back("--no-proxy");
  if (normals > 0) {
    args.emplace_back("--normals");
    args.push_back(std::to_string(normals));
  }
  if (!mode.machine.empty()) {
    args.emplace_back("--machine");
    args.push_back(mode.machine);
  }
  if (mode.axes > 0) {
    args.emplace_back("--axis-search");
    args.push_back(std::to_string(mode.axes));
  }
  if (mode.autoPose) {
    args.emplace_back("--pose");
    args.emplace_back("auto");
  }
  if (!mode.finalists.empty()) args.emplace_back(mode.finalists == "on" ? "--polish-finalists" : "--no-polish-finalists");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string log = plan.string() + ".log";
  std::fflush(stdout);  // or the child's freopen would write the table's pending lines again
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = fork();
  if (child == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen(log.c_str(), "w", stderr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  out.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.peakMiB = static_cast<double>(usage.ru_maxrss) / 1024.0;
  out.cpuSeconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                   1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    out.error = "multidir decompose failed (exit " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                "): see " + log;
    return out;
  }
  std::ifstream file(summary);
  const nlohmann::json json = nlohmann::json::parse(file, nullptr, false);
  if (json.is_discarded()) {
    out.error = "unreadable summary " + summary.string();
    return out;
  }
  out.ok = true;
  out.faces = json.value("triangles", 0LL);
  out.proxyFaces = json.value("proxy_faces", 0LL);
  out.searchSeconds = json.value("seconds", 0.0);
  out.regions = json.value("regions", 0LL);
  out.jgBefore = json.value("jg_before", 0.0);
  out.jgAfter = json.value("jg_after", 0.0);
  return out;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// The run repeated: the first run's plan (every run gives the same plan), the median seconds.
Outcome runRepeated(const Case& c, bool full, int normals, const SearchMode& mode, int repeat,
                    const fs::path& folder) {
  Outcome first = run(c, full, normals, mode, folder);
  std::vector<double> wall{first.wallSeconds}, cpu{first.cpuSeconds}, search{first.searchSeconds};
  for (int r = 1; first.ok && r < repeat; ++r) {
    const Outcome again = run(c, full, normals, mode, folder);
    if (!again.ok) return again;
    wall.push_back(again.wallSeconds);
    cpu.push_back(again.cpuSeconds);
    search.push_back(again.searchSeconds);
    first.peakMiB = std::max(first.peakMiB, again.peakMiB);
  }
  first.wallSeconds = median(wall);
  first.cpuSeconds = median(cpu);
  first.searchSeconds = median(search);
  return first;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> models{"kitten", "bunny", "fertility"};
  std::vector<int> levels{0, 1, 2, 3};
  bool million = false, full = false;
  double noiseMm = 0.02;
  int repeat = 1;
  std::vector<int> normalCounts{0};  // 0: the CLI's default
  std::string keep;
  SearchMode searchMode;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--million") million = true;
    else if (flag == "--full") full = true;
    else if (i + 1 < argc && flag == "--models") models = commaList(argv[++i]);
    else if (i + 1 < argc && flag == "--noise") noiseMm = std::atof(argv[++i]);
    else if (i + 1 < argc && flag == "--keep") keep = argv[++i];
    else if (i + 1 < argc && flag == "--machine") searchMode.machine = argv[++i];
    else if (i + 1 < argc && flag == "--axes") searchMode.axes = std::atoi(argv[++i]);
    else if (i + 1 < argc && flag == "--pose") searchMode.autoPose = std::string(argv[++i]) == "auto";
    else if (i + 1 < argc && flag == "--finalists") searchMode.finalists = argv[++i];
    else if (i + 1 < argc && flag == "--repeat") repeat = std::max(1, std::atoi(argv[++i]));
    else if (i + 1 < argc && flag == "--normals") {
      normalCounts.clear();
      for (const std::string& n : commaList(argv[++i])) normalCounts.push_back(std::atoi(n.c_str()));
    }
    else if (i + 1 < argc && flag == "--levels") {
      levels.clear();
      for (const std::string& l : commaList(argv[++i])) levels.push_back(std::atoi(l.c_str()));
    } else {
      std::fprintf(stderr, "unknown option %s (see the comment at the top of bench/scaling_bench.cpp)\n", flag.c_str());
      return 2;
    }
  }
  const fs::path folder = keep.empty() ? fs::temp_directory_path() / ("multidir-scaling-" + std::to_string(getpid()))
                                       : fs::path(keep);
  fs::create_directories(folder);

  std::vector<Case> cases;
  for (const std::string& model : models)
    for (int level : levels) cases.push_back({model + " " + std::to_string(1 << (2 * level)) + "x", model, level, 0.0, ""});
  if (million) {
    cases.push_back({"knight 1024x", "knight", 5, 0.0, ""});
    cases.push_back({"knight 1024x noisy", "knight", 5, noiseMm, ""});
  }

  std::printf("%-20s %5s %7s %10s %8s %8s %8s %8s %9s %7s %8s %9s\n", "model", "mode", "normals", "faces", "proxy",
              "wall s", "CPU s", "search s", "peak MiB", "regions", "after %", "x of 1x");
  std::map<std::string, double> baseline;  // model + mode + normals -> wall seconds at level 0
  std::map<std::string, std::vector<double>> draws;  // case + mode -> J_G after / before (%) per normal count
  std::vector<std::string> drawOrder;
  for (Case& c : cases) {
    if (!writeCase(c, folder)) return 1;
    for (const int normals : normalCounts)
      for (const bool fullSearch : full ? std::vector<bool>{false, true} : std::vector<bool>{false}) {
        const Outcome o = runRepeated(c, fullSearch, normals, searchMode, repeat, folder);
        const char* mode = fullSearch ? "full" : "proxy";
        const std::string normalsText = normals > 0 ? std::to_string(normals) : "default";
        if (!o.ok) {
          std::printf("%-20s %5s %7s %s\n", c.name.c_str(), mode, normalsText.c_str(), o.error.c_str());
          continue;
        }
        const std::string key = c.model + mode + (c.noiseMm > 0 ? "noisy" : "") + normalsText;
        if (c.level == 0) baseline[key] = o.wallSeconds;
        char ratio[32] = "-";
        if (baseline.count(key)) std::snprintf(ratio, sizeof ratio, "%.1f", o.wallSeconds / baseline[key]);
        const double afterPercent = o.jgBefore > 0 ? 100.0 * o.jgAfter / o.jgBefore : 0.0;
        std::printf("%-20s %5s %7s %10lld %8lld %8.2f %8.2f %8.2f %9.0f %7lld %8.2f %9s\n", c.name.c_str(), mode,
                    normalsText.c_str(), o.faces, o.proxyFaces, o.wallSeconds, o.cpuSeconds, o.searchSeconds, o.peakMiB, o.regions,
                    afterPercent, ratio);
        std::fflush(stdout);
        const std::string drawKey = c.name + " " + mode;
        if (!draws.count(drawKey)) drawOrder.push_back(drawKey);
        draws[drawKey].push_back(afterPercent);
      }
  }
  if (normalCounts.size() > 1) {
    std::printf("\nJ_G after / before over the %zu normal counts:\n%-26s %8s %8s %8s\n", normalCounts.size(),
                "model, mode", "median %", "min %", "max %");
    for (const std::string& key : drawOrder) {
      const std::vector<double>& d = draws[key];
      std::printf("%-26s %8.2f %8.2f %8.2f\n", key.c_str(), median(d), *std::min_element(d.begin(), d.end()),
                  *std::max_element(d.begin(), d.end()));
    }
  }
  if (keep.empty()) fs::remove_all(folder);
  return 0;
}
