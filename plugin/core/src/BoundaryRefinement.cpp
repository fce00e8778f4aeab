#include "omnirange/core/BoundaryRefinement.h"

#include <algorithm>

namespace omnirange
{
namespace
{
constexpr int kMixed = 2;  // pixels each side of the hit that may be mixtures
constexpr int kReference = 3;  // pixels averaged for each pure colour, beyond those

/** Mean colour of pixels [from, to) of the scanline. */
void meanColour(const std::uint8_t* bgr, const std::int32_t* pixels, int from, int to, double out[3])
{
	out[0] = out[1] = out[2] = 0;
	for (int k = from; k < to; ++k)
		for (int c = 0; c < 3; ++c) out[c] += bgr[3 * static_cast<std::size_t>(pixels[k]) + c];
	for (int c = 0; c < 3; ++c) out[c] /= (to - from);
}
}  // namespace

double refineBoundary(const std::uint8_t* bgr, const std::int32_t* pixels, int count, int hit, double reach,
					  double min_contrast)
{
	const double midpoint = hit - 0.5;
	const int first_mixed = hit - kMixed, last_mixed = hit + kMixed;
	if (first_mixed - kReference < 0 || last_mixed + 1 + kReference > count) return midpoint;
	double floor[3], obstacle[3];
	meanColour(bgr, pixels, first_mixed - kReference, first_mixed, floor);
	meanColour(bgr, pixels, last_mixed + 1, last_mixed + 1 + kReference, obstacle);
	const double d[3] = {obstacle[0] - floor[0], obstacle[1] - floor[1], obstacle[2] - floor[2]};
	const double d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
	if (d2 < min_contrast * min_contrast) return midpoint;
	// Pixels before first_mixed are floor; each mixed pixel adds its floor fraction.
	double edge = first_mixed - 0.5;
	for (int k = first_mixed; k <= last_mixed; ++k)
	{
		const std::uint8_t* px = bgr + 3 * static_cast<std::size_t>(pixels[k]);
		const double t = ((px[0] - floor[0]) * d[0] + (px[1] - floor[1]) * d[1] + (px[2] - floor[2]) * d[2]) / d2;
		edge += std::clamp(1.0 - t, 0.0, 1.0);
	}
	// Stay near what the classifier said: up to `reach` past its hit.
	return std::clamp(edge, hit - 1.5, hit + std::max(0.0, reach));
}

}  // namespace omnirange
