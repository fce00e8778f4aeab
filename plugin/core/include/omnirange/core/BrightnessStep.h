#pragma once
// A second cue for where the floor ends, beside colour: a step in brightness
// along the scanline. Where a wall or an object has the floor's colour (paint
// like the tiles, a grey floor among grey steel), the colour model sees
// through it; but its foot is still an edge, because a vertical face is lit
// unlike the floor. A step begins at pixel k when the mean brightness
// (B + G + R) of the `window` pixels from k on and that of the `window` pixels
// before k differ by a ratio of at least e^threshold. A ratio, so exposure,
// which multiplies every pixel alike, does not move it; brightness, not each
// channel, because a dark channel is mostly noise; means over a window, so a
// thin line (tile joints, plank seams, noise) moves it far less than a
// face's edge. Off (threshold 0) unless learning finds it helps (docs/method.md).

#include <cstdint>
#include <string>

namespace omnirange
{
/** Grey levels added to a brightness (B + G + R) before it enters a ratio:
 * near black, sensor noise alone makes large ratios (4 per channel). */
inline constexpr double kDarkBrightnessOffset = 12.0;

/** Which steps end a ray, by the side the brighter window is on. */
enum class StepSign
{
	Either,
	/** Only where what lies beyond is brighter: a floor's shadows (under an
	 * object, cast by the sun) are steps down, and are never taken for a face. */
	Brighter,
	/** Only where what lies beyond is darker (faces in shade, dark skirting). */
	Darker
};
std::string toString(StepSign s);
/** "either", "brighter" or "darker"; throws std::invalid_argument otherwise. */
StepSign stepSignFromString(const std::string& name);

/** The first step in [from, to] of a scanline (pixel k at `bgr + 3 *
 * pixels[k]`, `count` pixels) where a step of at least `threshold` (natural
 * log of the ratio of the window means), at its foot: the pixel, at most
 * `window` past where the ratio first reaches it, where it peaks; -1 if
 * none. Pixels without
 * `window` neighbours on either side are not tested. `sign` says which
 * steps count: beyond brighter, darker, or either. */
int findBrightnessStep(const std::uint8_t* bgr, const std::int32_t* pixels, int count, int from, int to,
					   double threshold, int window, StepSign sign = StepSign::Either);

}  // namespace omnirange
