#include "omnirange/config/Temporaries.h"

#include <pthread.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace omnirange::temporaries
{
namespace
{
// Never destroyed: the exit() handler below may run after the statics'
// destructors would have.
std::mutex& lock()
{
	static auto* m = new std::mutex;
	return *m;
}
std::set<std::string>& paths()
{
	static auto* p = new std::set<std::string>;
	return *p;
}
std::atomic<pid_t> child{0};
std::atomic<bool> interrupting{false};
// InterruptsDeferred: how many live, and how deep this thread is in them.
std::mutex deferred_mutex;
std::condition_variable deferred_ended;
int deferring = 0;
thread_local int deferring_here = 0;
std::string& program()
{
	static auto* p = new std::string;
	return *p;
}
std::string& activity()
{
	static auto* a = new std::string;
	return *a;
}

/** Other threads may still be adding files (a folder is not empty when its
 * last entry goes): try again a few times. */
void removeWhileOthersWrite(const std::string& p)
{
	std::error_code ec;
	for (int attempt = 0; attempt < 20 && std::filesystem::exists(p, ec); ++attempt) std::filesystem::remove_all(p, ec);
}

/** With the lock held: removes every remembered path. */
void removeAllHeld()
{
	for (const auto& p : paths()) removeWhileOthersWrite(p);
	paths().clear();
}

void atExit()
{
	// Another thread may hold the lock while exit() runs: do not wait for it long.
	std::unique_lock<std::mutex> g(lock(), std::defer_lock);
	for (int i = 0; i < 100 && !g.try_lock(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
	// A normal exit: everything was committed or removed, and the app said it was done (runApp()).
	if (!g.owns_lock() || (paths().empty() && activity().empty())) return;
	const bool unfinished = !paths().empty();
	removeAllHeld();
	std::fprintf(stderr, "%s: error: ended by a library (its message is above) while %s%s\n", program().c_str(),
				 activity().empty() ? "running" : activity().c_str(),
				 unfinished ? "; its unfinished outputs were removed" : "");
}
}  // namespace

void add(const std::string& path)
{
	const std::lock_guard<std::mutex> g(lock());
	paths().insert(path);
}

void forget(const std::string& path)
{
	const std::lock_guard<std::mutex> g(lock());
	paths().erase(path);
}

bool holds(const std::string& path)
{
	const std::lock_guard<std::mutex> g(lock());
	std::error_code ec;
	for (const auto& p : paths())
		if (std::filesystem::equivalent(p, path, ec)) return true;
	return false;
}

void setChild(int pid) { child.store(pid); }

void removeAtExit(const std::string& name)
{
	program() = name;
	static const bool registered = (std::atexit(atExit), true);
	(void)registered;
}

void setActivity(const std::string& what)
{
	const std::lock_guard<std::mutex> g(lock());
	activity() = what;
}

void warn(const std::string& what)
{
	std::fprintf(stderr, "%s: warning: %s\n", program().empty() ? "omnirange" : program().c_str(), what.c_str());
}

std::string currentActivity()
{
	const std::lock_guard<std::mutex> g(lock());
	return activity();
}

void removeAll()
{
	const std::lock_guard<std::mutex> g(lock());
	removeAllHeld();
}

void removeOnInterrupt()
{
	// The signals are blocked in every thread (threads started later inherit
	// the mask) and taken by one thread of ours with sigwait(): the cleanup
	// then runs as ordinary code, not inside a signal handler that may have
	// interrupted malloc.
	sigset_t set;
	sigemptyset(&set);
	sigaddset(&set, SIGINT);
	sigaddset(&set, SIGTERM);
	if (pthread_sigmask(SIG_BLOCK, &set, nullptr) != 0) return;
	std::thread([set] {
		int sig = 0;
		if (sigwait(&set, &sig) != 0) return;
		{
			std::unique_lock<std::mutex> g(deferred_mutex);
			interrupting.store(true);
			deferred_ended.wait_for(g, std::chrono::seconds(30), [] { return deferring == 0; });
		}
		// A program still writing into a temporary folder ends first.
		if (const pid_t c = child.load(); c > 0)
		{
			::kill(c, SIGTERM);
			::waitpid(c, nullptr, 0);
		}
		removeAll();
		// End the way the signal would have ended the run.
		std::signal(sig, SIG_DFL);
		sigset_t one;
		sigemptyset(&one);
		sigaddset(&one, sig);
		pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
		std::raise(sig);
	}).detach();
}

InterruptsDeferred::InterruptsDeferred()
{
	std::unique_lock<std::mutex> g(deferred_mutex);
	if (deferring_here == 0 && interrupting.load())
	{
		g.unlock();
		waitForInterrupt();
	}
	++deferring, ++deferring_here;
}

InterruptsDeferred::~InterruptsDeferred()
{
	const std::lock_guard<std::mutex> g(deferred_mutex);
	--deferring, --deferring_here;
	deferred_ended.notify_all();
}

bool interrupted() { return interrupting.load(); }

void waitForInterrupt()
{
	for (;;) ::pause();
}

namespace
{
/** The fields of /proc/PID/stat after the command's name: [0] the state, [19] the start time. */
std::vector<std::string> statOf(const std::string& pid)
{
	std::ifstream f("/proc/" + pid + "/stat");
	std::string line;
	std::getline(f, line);
	const auto end_of_name = line.rfind(')');
	std::vector<std::string> fields;
	if (end_of_name == std::string::npos) return fields;
	std::istringstream in(line.substr(end_of_name + 1));
	for (std::string v; in >> v;) fields.push_back(v);
	return fields;
}
}  // namespace

std::string thisRun()
{
	const std::string pid = std::to_string(::getpid());
	const auto stat = statOf(pid);
	return pid + " " + (stat.size() > 19 ? stat[19] : "");
}

bool runGone(const std::string& pid, const std::string& start)
{
	if (pid.empty() || pid.size() > 9 || pid.find_first_not_of("0123456789") != std::string::npos) return false;
	const long id = std::stol(pid);
	// This PID is this run's: another run's in a PID namespace before (a container's PID 1), if it started otherwise.
	if (id == ::getpid()) return !start.empty() && thisRun() != pid + " " + start;
	if (::kill(static_cast<pid_t>(id), 0) != 0) return errno == ESRCH;
	const auto stat = statOf(pid);
	if (!stat.empty() && stat[0] == "Z") return true;  // killed, not yet reaped by its parent
	return !start.empty() && stat.size() > 19 && stat[19] != start;
}

}  // namespace omnirange::temporaries
