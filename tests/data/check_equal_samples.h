#pragma once
// check_equal_samples: every field of two sample records compared exactly,
// as a stored sample must read back bit for bit (Catch2 CHECKs, so that a
// failure names the field).
#include <softchain/data/actuation_database.h>

#include <catch2/catch.hpp>

#include <cmath>

namespace softchain::testing
{
  inline void check_equal_samples(const data::SampleRecord &a, const data::SampleRecord &b)
  {
    CHECK(a.id == b.id);
    CHECK(a.actuation.canonical_text() == b.actuation.canonical_text());
    CHECK(a.actuation.pressure == b.actuation.pressure); // not in the text under volume control
    CHECK(a.actuation.cavity_volume_ratio == b.actuation.cavity_volume_ratio);
    CHECK(a.actuation.role == b.actuation.role);
    CHECK(a.status == b.status);
    CHECK(a.reason == b.reason);
    CHECK(a.load_factor_reached == b.load_factor_reached);
    CHECK(a.newton_iterations == b.newton_iterations);
    CHECK(a.load_steps == b.load_steps);
    CHECK(a.wall_time == b.wall_time);
    CHECK(a.x == b.x);
    CHECK(a.force_points_deformed == b.force_points_deformed);
    CHECK(a.base_force == b.base_force);
    CHECK(a.base_moment == b.base_moment);
    CHECK(((std::isnan(a.force_limit) && std::isnan(b.force_limit)) || a.force_limit == b.force_limit));
    REQUIRE(a.obstacle_wrenches.size() == b.obstacle_wrenches.size());
    for (std::size_t k = 0; k < a.obstacle_wrenches.size(); ++k)
      {
        CHECK(a.obstacle_wrenches[k].force == b.obstacle_wrenches[k].force);
        CHECK(a.obstacle_wrenches[k].moment == b.obstacle_wrenches[k].moment);
      }
  }
} // namespace softchain::testing
