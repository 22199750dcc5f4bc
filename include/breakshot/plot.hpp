// SVG plots of a run (src/io/svg_plot.cpp), drawn from a trace (lab.hpp).
#pragma once

#include <string>
#include <vector>

#include "breakshot/scenario.hpp"
#include "breakshot/simulation.hpp"

namespace breakshot {

/// Writes PREFIX-trajectories.svg, PREFIX-energy.svg and
/// PREFIX-momentum.svg from a trace. Returns the paths written. Throws
/// std::runtime_error naming the file if one cannot be written.
std::vector<std::string> write_plots(const Scenario& scenario,
                                     const std::vector<Sample>& frames,
                                     const std::string& prefix);

}  // namespace breakshot
