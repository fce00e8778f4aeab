#include "omnirange/core/BrightnessStep.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace omnirange
{
std::string toString(StepSign s)
{
	switch (s)
	{
		case StepSign::Either: return "either";
		case StepSign::Brighter: return "brighter";
		case StepSign::Darker: return "darker";
	}
	throw std::logic_error("unknown StepSign");
}

StepSign stepSignFromString(const std::string& name)
{
	if (name == "either") return StepSign::Either;
	if (name == "brighter") return StepSign::Brighter;
	if (name == "darker") return StepSign::Darker;
	throw std::invalid_argument("step_sign must be 'either', 'brighter' or 'darker', not '" + name + "'");
}

int findBrightnessStep(const std::uint8_t* bgr, const std::int32_t* pixels, int count, int from, int to,
					   double threshold, int window, StepSign sign)
{
	if (threshold <= 0 || window < 1) return -1;
	from = std::max(from, window);
	to = std::min(to, count - window);
	if (from > to) return -1;
	const double ratio = std::exp(threshold), offset = kDarkBrightnessOffset * window;
	// Brightness, B + G + R: a single channel is too noisy where it is dark
	// (a green floor's blue), and a face the floor's colour differs in brightness.
	const auto at = [&](int k) {
		const std::uint8_t* px = bgr + 3 * static_cast<std::size_t>(pixels[k]);
		return px[0] + px[1] + px[2];
	};
	// Running sums of the windows [k - window, k) and [k, k + window).
	int before = 0, after = 0;
	for (int j = 0; j < window; ++j) before += at(from - window + j), after += at(from + j);
	const bool up = sign != StepSign::Darker, down = sign != StepSign::Brighter;
	int found = -1, first = -1;  // the peak so far; where the ratio first reached the threshold
	double best = 0;
	for (int k = from; k <= to; ++k)
	{
		if (k > from)
		{
			const int leaving = at(k - 1);
			before += leaving - at(k - 1 - window);
			after += at(k - 1 + window) - leaving;
		}
		const double b = before + offset, a = after + offset;
		if (found < 0)
		{
			if ((up && a >= ratio * b) || (down && b >= ratio * a)) found = first = k, best = std::max(a / b, b / a);
			continue;
		}
		// The windows straddle the step from `window` pixels before its foot;
		// the foot is where they differ most: the first maximum after crossing,
		// at most `window` pixels on (a slow fall in light keeps rising).
		const double c = std::max(a / b, b / a);
		if (c <= best || k > first + window) break;
		found = k, best = c;
	}
	return found;
}

}  // namespace omnirange
