#include <gtest/gtest.h>
TEST(GroundTruthJson, Placeholder) {}
