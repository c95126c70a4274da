#include "app/StandardOutput.hpp"

#include "app/ProjectInput.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

namespace speculum::app {

namespace {

// A text longer than stdout's buffer (the usage) failed while it was written, and what failed then is no
// longer in errno. The output is lost either way, so one more byte asks the file why.
int causeOfEarlierFailure() {
    std::clearerr(stdout);
    errno = 0;
    if (std::fputc('\n', stdout) != EOF && std::fflush(stdout) == 0)
        return EIO; // it takes bytes again: what failed before is unknown
    return errno != 0 ? errno : EIO;
}

} // namespace

int finishStandardOutput(int status) {
    errno = 0;
    std::cout.flush();
    const bool streamFailed = !std::cout;
    const bool flushFailed = std::fflush(stdout) != 0;
    int error = errno;
    if (!streamFailed && !flushFailed && !std::ferror(stdout))
        return status;
    if (error == 0)
        error = causeOfEarlierFailure();
    printError(std::string("could not write the output to standard output: ") +
               std::strerror(error != 0 ? error : EIO));
    return status != 0 ? status : 1;
}

} // namespace speculum::app
