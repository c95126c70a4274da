#include "app/StandardOutput.hpp"

#include "app/ProjectInput.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

namespace speculum::app {

int finishStandardOutput(int status) {
    errno = 0;
    std::cout.flush();
    const bool streamFailed = !std::cout;
    const bool flushFailed = std::fflush(stdout) != 0;
    const int error = errno;
    if (!streamFailed && !flushFailed && !std::ferror(stdout))
        return status;
    printError(std::string("could not write the output to standard output: ") +
               std::strerror(error != 0 ? error : EIO));
    return status != 0 ? status : 1;
}

} // namespace speculum::app
