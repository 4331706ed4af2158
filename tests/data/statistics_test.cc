// data::median on counts odd, even and zero, unsorted input.
#include <softchain/data/statistics.h>

#include <catch2/catch.hpp>

#include <cmath>

TEST_CASE("the median of odd and even counts, and of none")
{
  using softchain::data::median;
  CHECK(median({3.0, 1.0, 2.0}) == 2.0);
  CHECK(median({4.0, 1.0, 3.0, 2.0}) == 2.5); // the mean of the middle two
  CHECK(median({7.0}) == 7.0);
  CHECK(std::isnan(median({})));
}
