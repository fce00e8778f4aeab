#pragma once
// Where exactly along a scanline the floor ends, to a fraction of a pixel.
// The classifier says which pixels are floor; the pixels at the edge are
// mixtures (anti-aliasing, lens blur, JPEG), and a mixture is rarely a floor
// colour, so the first non-free pixel lies up to a pixel or two before the
// true edge: a short bias that grows with range. Here each pixel near the
// candidate is taken as a mix of the floor's colour (measured just before
// it) and the obstacle's (just after); its floor fraction is the projection
// of its colour on the line between the two, and the edge lies where those
// fractions add up to: for a step blurred by any symmetric kernel, that is
// the step's position.

#include <cstdint>

namespace omnirange
{
enum class BoundaryModel
{
	Midpoint,  ///< halfway between the last free and the first non-free pixel (the paper's)
	Subpixel  ///< the floor fractions of the mixed pixels around it, summed
};

/** The farthest past the search's hit that refineBoundary can place the
 * edge [px]: its mixed pixels reach two pixels beyond the hit. */
inline constexpr double kMaxBoundaryReach = 2.5;

/** Fractional pixel index where the floor ends along a scanline whose pixel
 * k is at `bgr + 3 * pixels[k]` (pixel k spans [k - 0.5, k + 0.5]); `hit` is
 * the search's hit, count the scanline's length. The edge is kept within
 * [hit - 1.5, hit + reach]: a floor darkened near its edge (a shadow at a
 * wall's foot, vignetting, blur) leaves its last pixels non-free, and the
 * edge the colours show can lie two pixels past the hit. Falls back to the
 * midpoint (hit - 0.5) where floor and obstacle colours differ by less than
 * `min_contrast` grey levels or the scanline is too short around the hit. */
double refineBoundary(const std::uint8_t* bgr, const std::int32_t* pixels, int count, int hit,
					  double reach = kMaxBoundaryReach, double min_contrast = 12.0);

}  // namespace omnirange
