#pragma once
// What the run is doing, for the messages that must name it: a library that
// ends the program from inside (libjpeg, through MRPT, on a corrupt JPEG
// stored in a rawlog) or an allocation that fails names no file of its own.

#include <string>

namespace omnirange::activity
{
/** At exit(), unless the run has ended (set("") by runApp()): "PROGRAM:
 * error: ended by a library (its message is above) while WHAT". */
void nameExitsAs(const std::string& program);
/** What the run is doing, as "reading rawlog 'X'"; "" when it has ended. */
void set(const std::string& what);
/** What set() last said ("" if nothing). */
std::string current();
/** "PROGRAM: warning: what" on stderr, PROGRAM as nameExitsAs() named it:
 * what a library keeps of the user's and the user should hear of. */
void warn(const std::string& what);
}  // namespace omnirange::activity
