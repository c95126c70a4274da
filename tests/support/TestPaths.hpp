#pragma once

#include <string>
#include <string_view>

// Where the tests find the sources, write their files and find the speculum binary. The folders are this
// build's own, so they are defined in one file the build generates (TestPaths.cpp in the build folder):
// every other test file compiles to the same object in any clone, and a second clone on the same machine
// takes it from the compiler cache instead of compiling it again.
namespace speculum {

// The source root, or a path below it: testSourcePath("resources/scenes") (no trailing slash when empty).
std::string testSourcePath(std::string_view relative = {});
// The build's folder for test output, or a path below it.
std::string testDataPath(std::string_view relative = {});
// The speculum binary of this build, for the tests that run it as a user would (USES_CLI).
const std::string& testCliBinary();

} // namespace speculum
