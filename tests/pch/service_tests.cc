// Compiles tests/pch/service_tests.h once; see tests/CMakeLists.txt.
