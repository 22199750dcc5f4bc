// breakshot._core.play_shots: batch shots (breakshot/batch.hpp) on numpy
// arrays, with the GIL released while the shots run. The package's
// breakshot.shots (python/breakshot/shots.py) wraps it.
#include <pybind11/numpy.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "bind.hpp"
#include "breakshot/batch.hpp"
#include "breakshot/noise.hpp"

namespace breakshot::python {

namespace {

template <class T>
py::array_t<T> array(std::vector<py::ssize_t> shape) {
  return py::array_t<T>(std::move(shape));
}

/// The batch's vectors as numpy arrays (copied: a few bytes per ball and
/// shot, against microseconds of simulation).
py::dict to_arrays(const ShotBatch& b) {
  const auto k = static_cast<py::ssize_t>(b.shots);
  const auto n = static_cast<py::ssize_t>(b.balls);
  auto pos = array<double>({k, n, 2});
  auto pockets = array<std::int32_t>({k, n});
  auto cushions = array<std::int32_t>({k, n});
  auto cue = array<std::int32_t>({k});
  auto first = array<std::int32_t>({k});
  auto before = array<std::int32_t>({k});
  auto events = array<std::int64_t>({k});
  auto times = array<double>({k});
  auto complete = array<bool>({k});
  auto miscue = array<bool>({k});
  auto played = array<double>({k, 5});
  {
    auto p = pos.mutable_unchecked<3>();
    auto pk = pockets.mutable_unchecked<2>();
    auto cu = cushions.mutable_unchecked<2>();
    auto ci = cue.mutable_unchecked<1>();
    auto fh = first.mutable_unchecked<1>();
    auto bh = before.mutable_unchecked<1>();
    auto ev = events.mutable_unchecked<1>();
    auto ti = times.mutable_unchecked<1>();
    auto co = complete.mutable_unchecked<1>();
    auto mi = miscue.mutable_unchecked<1>();
    auto pl = played.mutable_unchecked<2>();
    for (py::ssize_t j = 0; j < k; ++j) {
      const auto uj = static_cast<std::size_t>(j);
      for (py::ssize_t i = 0; i < n; ++i) {
        const std::size_t at = uj * b.balls + static_cast<std::size_t>(i);
        p(j, i, 0) = b.final_positions[at].x;
        p(j, i, 1) = b.final_positions[at].y;
        pk(j, i) = b.pockets[at];
        cu(j, i) = b.cushions[at];
      }
      ci(j) = b.cue_index[uj];
      fh(j) = b.first_hit[uj];
      bh(j) = b.cushions_before_hit[uj];
      ev(j) = static_cast<std::int64_t>(b.event_counts[uj]);
      ti(j) = b.final_times[uj];
      co(j) = b.complete[uj] != 0;
      mi(j) = b.miscue[uj] != 0;
      const CueStrike& s = b.played[uj];
      pl(j, 0) = s.phi;
      pl(j, 1) = s.theta;
      pl(j, 2) = s.speed;
      pl(j, 3) = s.a;
      pl(j, 4) = s.b;
    }
  }
  py::dict d;
  d["final_positions"] = pos;
  d["pockets"] = pockets;
  d["cushions"] = cushions;
  d["cue_index"] = cue;
  d["first_hit"] = first;
  d["cushions_before_hit"] = before;
  d["event_counts"] = events;
  d["final_times"] = times;
  d["complete"] = complete;
  d["miscue"] = miscue;
  d["played"] = played;
  return d;
}

}  // namespace

void bind_shots(py::module_& m) {
  m.def(
      "play_shots",
      [](py::object scenarios, bool one,
         py::array_t<double, py::array::c_style | py::array::forcecast> strikes,
         unsigned threads, const std::string& noise, std::uint64_t seed) {
        // The scenarios: parsed ones are used in place (the list holds
        // them), the others are read here.
        py::list held;
        std::vector<Scenario> read;
        std::vector<const Scenario*> ptrs;
        const py::list given = one ? py::list() : py::list(scenarios);
        const std::size_t count = one ? 1 : given.size();
        read.reserve(count);
        for (std::size_t j = 0; j < count; ++j) {
          py::handle h = one ? scenarios : given[j];
          held.append(h);
          if (py::isinstance<Scenario>(h)) {
            ptrs.push_back(&h.cast<const Scenario&>());
            continue;
          }
          try {
            read.push_back(scenario_arg(h));
          } catch (ScenarioRefused& e) {
            if (!one) e.error.path = "scenarios[" + std::to_string(j) + "]." + e.error.path;
            throw;
          }
          ptrs.push_back(&read.back());
        }
        for (std::size_t j = 0; j < ptrs.size(); ++j) {
          if (auto e = check_shot_scenario(*ptrs[j], "")) {
            if (!one) e->path = "scenarios[" + std::to_string(j) + "]." + e->path;
            throw ScenarioRefused{*e};
          }
        }

        if (strikes.ndim() != 2 || strikes.shape(1) != 5) {
          throw py::value_error("strikes: expected an array of shape (k, 5)");
        }
        const auto k = static_cast<std::size_t>(strikes.shape(0));
        auto s = strikes.unchecked<2>();
        std::vector<CueStrike> list(k);
        for (std::size_t j = 0; j < k; ++j) {
          const auto r = static_cast<py::ssize_t>(j);
          list[j] = CueStrike{s(r, 2), s(r, 0), s(r, 1), s(r, 3), s(r, 4)};
          if (auto e = check_strike(list[j], j)) throw py::value_error(e->path + ": " + e->reason);
        }

        ShotBatchOptions options;
        options.threads = threads;
        options.seed = seed;
        try {
          options.noise = parse_noise(noise);
        } catch (const std::invalid_argument& e) {
          throw py::value_error(std::string("noise: ") + e.what());
        }
        ShotBatch batch;
        {
          py::gil_scoped_release release;
          batch = play_shots(std::span<const Scenario* const>(ptrs), list, options);
        }
        py::dict out = to_arrays(batch);
        py::list ids, pockets;
        for (const BallSpec& b : ptrs[0]->balls) ids.append(b.id);
        for (const Pocket& p : ptrs[0]->table.pockets) pockets.append(p.name);
        out["ball_ids"] = ids;
        out["pocket_names"] = pockets;
        return out;
      },
      py::arg("scenarios"), py::arg("one"), py::arg("strikes"), py::arg("threads"),
      py::arg("noise"), py::arg("seed"),
      "Batch shots (breakshot.shots): a dict of numpy arrays. `one`: `scenarios` is one "
      "scenario for every strike, else a sequence of one per strike. Strikes are rows "
      "(phi, theta, speed, a, b); `noise` a parse_noise spec.");
}

}  // namespace breakshot::python
