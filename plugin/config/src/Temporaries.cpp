#include "omnirange/config/Temporaries.h"

#include <pthread.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <thread>

namespace omnirange::temporaries
{
namespace
{
/** What the run keeps for its interrupt and its exit: never destroyed, for the exit() handler below
 * may run after the statics' destructors would have. */
struct State
{
	std::mutex lock;
	std::recursive_mutex commits;
	std::set<std::string> paths;
	std::string program, activity;
};
State& state()
{
	static auto* s = new State;
	return *s;
}
std::atomic<pid_t> child{0};
std::atomic<bool> interrupting{false};

/** With the lock held: removes every remembered path (other threads may still be adding files: a few tries). */
void removeAllHeld()
{
	std::error_code ec;
	for (const auto& p : state().paths)
		for (int attempt = 0; attempt < 20 && std::filesystem::exists(p, ec); ++attempt) std::filesystem::remove_all(p, ec);
	state().paths.clear();
}

void atExit()
{
	// Another thread may hold the lock while exit() runs: do not wait for it long.
	std::unique_lock<std::mutex> g(state().lock, std::defer_lock);
	for (int i = 0; i < 100 && !g.try_lock(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
	// A normal exit: everything was committed or removed, and the app said it was done (runApp()).
	if (!g.owns_lock() || (state().paths.empty() && state().activity.empty())) return;
	const bool unfinished = !state().paths.empty();
	removeAllHeld();
	std::fprintf(stderr, "%s: error: ended by a library (its message is above) while %s%s\n", state().program.c_str(),
				 state().activity.empty() ? "running" : state().activity.c_str(), unfinished ? "; its unfinished outputs were removed" : "");
}
}  // namespace

void add(const std::string& path)
{
	const std::lock_guard<std::mutex> g(state().lock);
	state().paths.insert(path);
}

void forget(const std::string& path)
{
	const std::lock_guard<std::mutex> g(state().lock);
	state().paths.erase(path);
}

void setChild(int pid) { child.store(pid); }

void removeAtExit(const std::string& name)
{
	state().program = name;
	static const bool registered = (std::atexit(atExit), true);
	(void)registered;
}

void setActivity(const std::string& what)
{
	const std::lock_guard<std::mutex> g(state().lock);
	state().activity = what;
}

void warn(const std::string& what)
{
	std::fprintf(stderr, "%s: warning: %s\n", state().program.empty() ? "omnirange" : state().program.c_str(), what.c_str());
}

std::string currentActivity()
{
	const std::lock_guard<std::mutex> g(state().lock);
	return state().activity;
}

std::unique_lock<std::recursive_mutex> interruptsDeferred() { return std::unique_lock<std::recursive_mutex>(state().commits); }

void removeOnInterrupt()
{
	// The signals are blocked in every thread (threads started later inherit the mask) and taken by one
	// thread with sigwait(): the cleanup runs as ordinary code, not in a handler that may have cut malloc.
	sigset_t set;
	sigemptyset(&set);
	sigaddset(&set, SIGINT);
	sigaddset(&set, SIGTERM);
	if (pthread_sigmask(SIG_BLOCK, &set, nullptr) != 0) return;
	std::thread([set] {
		int sig = 0;
		if (sigwait(&set, &sig) != 0) return;
		interrupting.store(true);
		if (const pid_t c = child.load(); c > 0)  // a program still writing into a staging folder ends first
		{
			::kill(c, SIGTERM);
			::waitpid(c, nullptr, 0);
		}
		const auto no_commit = interruptsDeferred();  // held to the end: no commit begins after this
		{
			const std::lock_guard<std::mutex> g(state().lock);
			removeAllHeld();
		}
		// End the way the signal would have ended the run.
		std::signal(sig, SIG_DFL);
		sigset_t one;
		sigemptyset(&one);
		sigaddset(&one, sig);
		pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
		std::raise(sig);
	}).detach();
}

bool interrupted() { return interrupting.load(); }

void waitForInterrupt()
{
	for (;;) ::pause();
}

}  // namespace omnirange::temporaries
