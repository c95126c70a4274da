#pragma once

namespace speculum::app {

// A command's printed output (a report, JSON, the path of what it wrote) reaches its reader only when
// standard output is flushed, and a full disk, a file-size limit or a closed pipe shows only there or in
// the error flag a failed write leaves behind. Flushes it and checks: where the output did not arrive whole,
// says so in one line and turns `status` into a failure (keeping a failure's own status); otherwise returns
// `status` as it is.
int finishStandardOutput(int status);

} // namespace speculum::app
