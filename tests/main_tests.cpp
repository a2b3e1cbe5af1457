// doctest main for the ample-cpp test suite (see tests/CMakeLists.txt)
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
