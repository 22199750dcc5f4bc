// A test check shared by the simulation tests: two lists of ball states
// are the same, bit for bit in every field (doubles compared with ==).
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "breakshot/ball.hpp"

inline void expect_same_states(const std::vector<breakshot::BallState>& a,
                               const std::vector<breakshot::BallState>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].position, b[i].position) << "ball " << i;
    EXPECT_EQ(a[i].velocity, b[i].velocity) << "ball " << i;
    EXPECT_EQ(a[i].spin, b[i].spin) << "ball " << i;
    EXPECT_EQ(a[i].state, b[i].state) << "ball " << i;
  }
}
