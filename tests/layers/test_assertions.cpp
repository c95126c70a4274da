// Test builds keep assertions on: an assert that fires in a test is a bug found, and a build with NDEBUG
// would let it pass silently.
#include <cassert>
#include <gtest/gtest.h>

namespace {

TEST(TestBuild, HasAssertionsOn) {
#ifdef NDEBUG
    FAIL() << "this test build defines NDEBUG, so every assert() is off";
#endif
}

TEST(TestBuildDeathTest, AFalseAssertionAborts) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    EXPECT_DEATH(assert(1 + 1 == 3), "1 \\+ 1 == 3");
}

} // namespace
