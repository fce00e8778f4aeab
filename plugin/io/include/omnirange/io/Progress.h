#pragma once
// Progress of a long loop on stderr: on a terminal one line rewritten in
// place (at most ten times a second); otherwise a plain line now and then
// (every tenth of the total, or every 30 s when the total is unknown), so
// logs stay short. A window shows it instead through a callback.

#include <chrono>
#include <functional>
#include <string>

namespace omnirange
{
class Progress
{
   public:
	/** `what` names the unit counted ("images scanned"). */
	explicit Progress(std::string what);
	~Progress();
	Progress(const Progress&) = delete;
	Progress& operator=(const Progress&) = delete;

	/** Instead of printing: `show(done, total)` at most ten times a second. */
	using Callback = std::function<void(std::size_t done, std::size_t total)>;
	Progress(std::string what, Callback show);

	/** `done` of `total` (0: unknown). */
	void update(std::size_t done, std::size_t total = 0);
	/** Ends the line (the destructor does too); with a callback, shows the last count. */
	void finish();

   private:
	std::string what_;
	bool tty_;
	bool open_line_{false};
	std::size_t last_printed_{0};
	std::chrono::steady_clock::time_point start_, last_;
	Callback show_;
	std::size_t latest_done_{0}, latest_total_{0};  // what finish() shows the callback last
};

}  // namespace omnirange
