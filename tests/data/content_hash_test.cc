// content_hash: FNV-1a 64 test vectors from the FNV reference (Fowler, Noll,
// Vo; "FNV-1a 64 bit" of "" and "a"), and canonical doubles.
#include <softchain/data/content_hash.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>

using namespace softchain::data;

TEST_CASE("content hash is FNV-1a 64 and stable")
{
  CHECK(content_hash("") == "cbf29ce484222325");
  CHECK(content_hash("a") == "af63dc4c8601ec8c");
  CHECK(content_hash("foobar") == "85944171f73967e8");
  CHECK(content_hash("pressure 1") != content_hash("pressure 2"));
}

TEST_CASE("canonical doubles read back to the same value")
{
  for (const double v : {0.1, 1.0 / 3.0, -2.5e-300, 6.02214076e23})
    CHECK(std::strtod(canonical(v).c_str(), nullptr) == v);
  CHECK(canonical(0.1) != canonical(std::nextafter(0.1, 1.0))); // neighbours differ
}
