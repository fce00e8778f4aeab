#pragma once
// The staging folders a run has made and not yet committed (Output.h). An
// interrupted run (SIGINT, SIGTERM) removes them before it ends; one killed
// outright leaves them to the next run beside them.

#include <mutex>
#include <string>

namespace omnirange::temporaries
{
/** Remembers the staging folder `path` until forget(path). */
void add(const std::string& path);
void forget(const std::string& path);
/** The program a run has started and waits for (0: none): an interrupt
 * ends it first, so it writes nothing into a folder being removed. */
void setChild(int pid);
/** On SIGINT or SIGTERM: every remembered path removed, then the run ended by that signal as before. */
void removeOnInterrupt();
/** Held while a commit moves its outputs in: an interrupt waits for it,
 * so the moves are done whole or not begun. */
std::unique_lock<std::recursive_mutex> interruptsDeferred();
/** Whether an interrupt is being handled: what fails meanwhile (a program
 * ended for it, a folder removed under the run) is its consequence, not an
 * error to report; waitForInterrupt() lets it end the run. */
bool interrupted();
/** Blocks until the interrupt being handled ends the run. */
[[noreturn]] void waitForInterrupt();
/** At exit() too: a library that ends the program from inside (libjpeg,
 * through MRPT, on a corrupt JPEG stored in a rawlog) leaves no temporaries,
 * and "PROGRAM: error: ..." names what the run was doing (setActivity()). */
void removeAtExit(const std::string& program);
/** What the run is doing, for that message: "reading rawlog 'X'"; the run's
 * own end sets it to "" (a library that exits after that ended nothing). */
void setActivity(const std::string& what);
/** "PROGRAM: warning: what" on stderr, PROGRAM as removeAtExit() named it:
 * what a library keeps of the user's and the user should hear of. */
void warn(const std::string& what);
/** What setActivity() last said ("" if nothing): an error with no file of its own (out of memory) names it. */
std::string currentActivity();

}  // namespace omnirange::temporaries
