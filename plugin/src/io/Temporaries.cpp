#include "omnirange/io/Temporaries.h"

#include <pthread.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <mutex>
#include <set>
#include <thread>

namespace omnirange::temporaries
{
namespace
{
std::mutex& lock()
{
	static std::mutex m;
	return m;
}
std::set<std::string>& paths()
{
	static std::set<std::string> p;
	return p;
}
std::atomic<pid_t> child{0};

/** Other threads may still be adding files (a folder is not empty when its
 * last entry goes): try again a few times. */
void removeWhileOthersWrite(const std::string& p)
{
	std::error_code ec;
	for (int attempt = 0; attempt < 20 && std::filesystem::exists(p, ec); ++attempt) std::filesystem::remove_all(p, ec);
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

void setChild(int pid) { child.store(pid); }

void removeAll()
{
	const std::lock_guard<std::mutex> g(lock());
	for (const auto& p : paths()) removeWhileOthersWrite(p);
	paths().clear();
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

}  // namespace omnirange::temporaries
