// The one Catch2 main of all unit-test executables (compiled once: 20 s).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
