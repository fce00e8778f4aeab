#include "omnirange/config/Activity.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

namespace omnirange::activity
{
namespace
{
/** Never destroyed: the exit() handler may run after the statics' destructors would have. */
struct State
{
	std::mutex lock;
	std::string program, what;
};
State& state()
{
	static auto* s = new State;
	return *s;
}

void atExit()
{
	// Another thread may hold the lock while exit() runs: do not wait for it long.
	std::unique_lock<std::mutex> g(state().lock, std::defer_lock);
	for (int i = 0; i < 100 && !g.try_lock(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
	if (g.owns_lock() && !state().what.empty())
		std::fprintf(stderr, "%s: error: ended by a library (its message is above) while %s\n", state().program.c_str(),
					 state().what.c_str());
}
}  // namespace

void nameExitsAs(const std::string& program)
{
	state().program = program;
	static const bool registered = (std::atexit(atExit), true);
	(void)registered;
}

void set(const std::string& what)
{
	const std::lock_guard<std::mutex> g(state().lock);
	state().what = what;
}

std::string current()
{
	const std::lock_guard<std::mutex> g(state().lock);
	return state().what;
}

void warn(const std::string& what)
{
	std::fprintf(stderr, "%s: warning: %s\n", state().program.empty() ? "omnirange" : state().program.c_str(), what.c_str());
}
}  // namespace omnirange::activity
