// Everything public in one include.
#pragma once

#include "breakshot/ball.hpp"
#include "breakshot/event.hpp"
#include "breakshot/lab.hpp"
#include "breakshot/physics.hpp"
#include "breakshot/plot.hpp"
#include "breakshot/roots.hpp"
#include "breakshot/scenario.hpp"
#include "breakshot/scenario_io.hpp"
#include "breakshot/simulation.hpp"
#include "breakshot/table.hpp"
#include "breakshot/vec.hpp"
