#pragma once
// MRPT's programs (observations2map, rawlog-edit, icp-slam) run for real:
// started with an argument vector (never a shell string, so no path or ini
// value is ever interpreted), in a working folder, with no standard input
// (they read it and would wait), their output captured to a log file.

#include <string>
#include <vector>

namespace omnirange::eval
{
/** Runs argv[0] (looked up on PATH) with `argv` in `dir`; stdout and stderr
 * go to `dir`/`log`. Throws std::runtime_error naming the program, the log
 * and its last line if it cannot start or exits other than 0. */
void runProgram(const std::vector<std::string>& argv, const std::string& dir, const std::string& log);

}  // namespace omnirange::eval
