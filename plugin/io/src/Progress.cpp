#include "omnirange/io/Progress.h"

#include <unistd.h>

#include <cstdio>

namespace omnirange
{
Progress::Progress(std::string what)
	: what_(std::move(what)), tty_(::isatty(2) != 0), start_(std::chrono::steady_clock::now()), last_(start_)
{
}

Progress::Progress(std::string what, Callback show) : Progress(std::move(what))
{
	show_ = std::move(show);
	tty_ = true;  // the callback's pace: at most ten times a second
}

Progress::~Progress() { finish(); }

void Progress::update(std::size_t done, std::size_t total)
{
	latest_done_ = done, latest_total_ = total;
	const auto now = std::chrono::steady_clock::now();
	const double since = std::chrono::duration<double>(now - last_).count();
	const bool due = tty_ ? since >= 0.1 || done == total
						  : (total > 0 ? done * 10 / total > last_printed_ * 10 / total : since >= 30.0);
	if (!due || done == 0) return;
	last_ = now, last_printed_ = done;
	if (show_) return show_(done, total);
	const char* start = tty_ ? "\r" : "";
	const char* end = tty_ ? "\033[K" : "\n";  // on a terminal: clear the rest of the line
	if (total > 0 && done < total)
	{
		// Time left at the pace so far: rough, but it says whether to wait or come back.
		const double left = std::chrono::duration<double>(now - start_).count() * double(total - done) / double(done);
		std::fprintf(stderr, "%s%s: %zu/%zu (%.0f %%, about %.0f s left)%s", start, what_.c_str(), done, total,
					 100.0 * done / total, left, end);
	}
	else if (total > 0)
		std::fprintf(stderr, "%s%s: %zu/%zu (100 %%)%s", start, what_.c_str(), done, total, end);
	else
		std::fprintf(stderr, "%s%s: %zu%s", start, what_.c_str(), done, end);
	open_line_ = tty_;
	std::fflush(stderr);
}

void Progress::finish()
{
	if (show_ && latest_done_ > last_printed_)
	{
		last_printed_ = latest_done_;
		show_(latest_done_, latest_total_);
	}
	if (open_line_) std::fprintf(stderr, "\n");
	open_line_ = false;
}

}  // namespace omnirange
