// Helpers for the AI tests (test_ai.cpp, test_ai_snooker.cpp).
#pragma once

#include <string>

#include "breakshot/ai.hpp"

namespace ai_fixtures {

/// A small searching level: few candidates and samples, one thread, so
/// that a decision takes milliseconds even under the sanitizers.
inline breakshot::AiLevel small_level(const std::string& base = "expert") {
  breakshot::AiLevel l = breakshot::ai_level(base);
  l.candidates = 4;
  l.samples = 4;
  l.threads = 1;
  l.generation.speed_factors = {1.0, 1.6};
  l.generation.spins = {0.0};
  l.generation.refine_iterations = 2;
  l.generation.max_candidates = 24;
  return l;
}

}  // namespace ai_fixtures
