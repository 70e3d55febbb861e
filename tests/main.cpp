// The test binary's entry point (doctest). ctest runs it once per test suite.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
