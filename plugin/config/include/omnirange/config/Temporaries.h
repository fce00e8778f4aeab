#pragma once
// The temporary files and folders a run has made and not yet renamed into
// place. An interrupted run (SIGINT, SIGTERM) removes them before it ends,
// so it leaves no .NAME.tmp-PID files or half-filled image folders behind.

#include <string>

namespace omnirange::temporaries
{
/** Remembers `path` (a file or a folder) until forget(path). */
void add(const std::string& path);
void forget(const std::string& path);
/** Whether `path` is one of this process's temporaries (a staging folder it is filling), by what it is. */
bool holds(const std::string& path);
/** The program a run has started and waits for (0: none): an interrupt
 * ends it first, so it writes nothing into a folder being removed. */
void setChild(int pid);
/** Removes every remembered path (at an interrupt). */
void removeAll();
/** On SIGINT or SIGTERM: removeAll(), then end by that signal as before. */
void removeOnInterrupt();
/** While one lives, an interrupt waits for it to end (30 s at most): a
 * commit's renames are done whole or not begun, never cut half-way. Once an
 * interrupt is waiting, a new one (not inside another) waits for it to end the run. */
class InterruptsDeferred
{
   public:
	InterruptsDeferred();
	~InterruptsDeferred();
	InterruptsDeferred(const InterruptsDeferred&) = delete;
	InterruptsDeferred& operator=(const InterruptsDeferred&) = delete;
};
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

/** "PID START": this process, with its start time (a PID is reused later,
 * after a reboot soon; the pair is not). */
std::string thisRun();
/** The run `pid` (digits), started at `start` ("" to leave that out), is
 * over: no such process, one killed and not yet reaped, or another process
 * that has its PID now. Its leftovers are nobody's run's. */
bool runGone(const std::string& pid, const std::string& start = "");

}  // namespace omnirange::temporaries
