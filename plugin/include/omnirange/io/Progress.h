#pragma once
// Progress of a long loop on stderr: on a terminal one line rewritten in
// place (at most ten times a second); otherwise a plain line now and then
// (every tenth of the total, or every 30 s when the total is unknown), so
// logs stay short.

#include <chrono>
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

	/** `done` of `total` (0: unknown). */
	void update(std::size_t done, std::size_t total = 0);
	/** Ends the line (the destructor does too). */
	void finish();

   private:
	std::string what_;
	bool tty_;
	bool open_line_{false};
	std::size_t last_printed_{0};
	std::chrono::steady_clock::time_point last_;
};

}  // namespace omnirange
