// web_timing: the native half of the per-shot timing of
// web/tests/timing.mjs (docs/web.md, "Build and speed"). It plays the
// shots of a file through the facade (web/api/web_api.hpp) exactly as
// timing.mjs plays them through the wasm build, and prints its figures,
// so that the two are measured the same way on the same shots:
//
//   web_timing --shots FILE [--rounds N] [--warmup N]
//
// FILE: one shot a line, "WORKLOAD<TAB>SCENARIO" (the scenario's JSON on
// one line); workloads are the runs of equal names, in file order. A
// round makes two passes over each workload's shots: bs_web_playback_new and
// bs_web_playback_free of each ("new": the scenario's text read and set up),
// then the same with bs_web_playback_frame_data at t = 1e9 between them
// ("shot": set-up and the physics to rest). --warmup rounds (default 1)
// are not timed; the first of them also gives each workload's event
// count and a hash of its final frames (FNV-1a of the doubles' bytes),
// which timing.mjs compares with the wasm build's. Prints one JSON
// object a line per workload: {"workload", "shots", "events", "hash",
// "new_us", "shot_us", "new_cpu", "shot_cpu"}, the lists giving each
// timed pass's microseconds over all the workload's shots, wall-clock
// (_us) and the process's CPU time (_cpu: the steadier figure on a busy
// machine).

#include <chrono>
#include <ctime>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "web_api.hpp"

namespace {

struct Workload {
  std::string name;
  std::vector<std::string> shots;
  std::vector<double> new_us;
  std::vector<double> shot_us;
  std::vector<double> new_cpu;
  std::vector<double> shot_cpu;
  double events = 0.0;
  std::uint32_t hash = 2166136261u;
};

std::size_t frame_length(const double* d) {
  const auto n = static_cast<std::size_t>(d[7]);
  return 8 + 8 * n + 1 + 2 * n;
}

void hash_bytes(std::uint32_t& h, const double* d, std::size_t count) {
  const auto* b = reinterpret_cast<const unsigned char*>(d);
  for (std::size_t k = 0; k < count * sizeof(double); ++k) {
    h ^= b[k];
    h *= 16777619u;
  }
}

/// The process's CPU time in microseconds.
double cpu_us() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e6 + static_cast<double>(ts.tv_nsec) * 1e-3;
}

/// A pass over the workload's shots: bs_web_playback_new and
/// bs_web_playback_free of each, with bs_web_playback_frame_data to rest between
/// them when `run`. Adds its wall-clock and CPU microseconds to the
/// lists when `timed`; false when a call failed.
bool pass(Workload& w, bool run, bool timed, bool check) {
  using clock = std::chrono::steady_clock;
  const double c0 = cpu_us();
  const auto t0 = clock::now();
  for (const std::string& text : w.shots) {
    BsWebPlayback* pb = bs_web_playback_new(text.c_str());
    if (pb == nullptr) {
      std::cerr << "web_timing: " << w.name << ": " << bs_web_last_error() << '\n';
      return false;
    }
    if (run) {
      const double* d = bs_web_playback_frame_data(pb, 1e9);
      if (d == nullptr) {
        std::cerr << "web_timing: " << w.name << ": " << bs_web_last_error() << '\n';
        return false;
      }
      if (check) {
        w.events += d[1];
        hash_bytes(w.hash, d, frame_length(d));
      }
    }
    bs_web_playback_free(pb);
  }
  const double wall = std::chrono::duration<double, std::micro>(clock::now() - t0).count();
  const double cpu = cpu_us() - c0;
  if (timed) {
    (run ? w.shot_us : w.new_us).push_back(wall);
    (run ? w.shot_cpu : w.new_cpu).push_back(cpu);
  }
  return true;
}

void print_list(const std::vector<double>& v) {
  std::printf("[");
  for (std::size_t k = 0; k < v.size(); ++k) std::printf("%s%.3f", k > 0 ? "," : "", v[k]);
  std::printf("]");
}

}  // namespace

int main(int argc, char** argv) {
  std::string file;
  int rounds = 10;
  int warmup = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--shots" && i + 1 < argc) {
      file = argv[++i];
    } else if (a == "--rounds" && i + 1 < argc) {
      rounds = std::atoi(argv[++i]);
    } else if (a == "--warmup" && i + 1 < argc) {
      warmup = std::atoi(argv[++i]);
    } else {
      file.clear();
      break;
    }
  }
  if (file.empty() || rounds < 1 || warmup < 1) {
    std::cerr << "usage: web_timing --shots FILE [--rounds N >= 1] [--warmup N >= 1]\n";
    return 2;
  }
  std::ifstream in(file);
  if (!in) {
    std::cerr << "web_timing: cannot read " << file << '\n';
    return 1;
  }
  std::vector<Workload> workloads;
  std::string line;
  while (std::getline(in, line)) {
    const auto tab = line.find('\t');
    if (tab == std::string::npos) continue;
    const std::string name = line.substr(0, tab);
    if (workloads.empty() || workloads.back().name != name) workloads.push_back({name, {}, {}, {}, {}, {}});
    workloads.back().shots.push_back(line.substr(tab + 1));
  }
  for (int r = 0; r < warmup + rounds; ++r) {
    for (Workload& w : workloads) {
      if (!pass(w, false, r >= warmup, false) || !pass(w, true, r >= warmup, r == 0)) return 1;
    }
  }
  for (const Workload& w : workloads) {
    std::printf("{\"workload\":\"%s\",\"shots\":%zu,\"events\":%.0f,\"hash\":\"%08x\",\"new_us\":",
                w.name.c_str(), w.shots.size(), w.events, static_cast<unsigned>(w.hash));
    print_list(w.new_us);
    std::printf(",\"shot_us\":");
    print_list(w.shot_us);
    std::printf(",\"new_cpu\":");
    print_list(w.new_cpu);
    std::printf(",\"shot_cpu\":");
    print_list(w.shot_cpu);
    std::printf("}\n");
  }
  return 0;
}
