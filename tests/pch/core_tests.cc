// Compiles tests/pch/core_tests.h once; see tests/CMakeLists.txt.
