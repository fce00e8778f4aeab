#pragma once
// The seam between the polar scanner and a free-space model (paper §III-A):
// the scanner asks for the pixels of one scanline in short runs, so a model
// is called once per run rather than once per pixel, and pixels beyond the
// hit search's decision are never classified. Another model (two-class,
// other features) plugs in by implementing classify().

#include <cstdint>

namespace omnirange
{
/** What classify() writes per pixel. A model that knows no doubt writes
 * only kNotFree and kFree, and every free pixel it sees is sure floor. */
inline constexpr std::uint8_t kNotFree = 0;
inline constexpr std::uint8_t kFree = 1;  ///< free, and the colour is sure floor
inline constexpr std::uint8_t kDoubtfulFree = 3;  ///< free, but a colour the floor rarely shows

class PixelClassifier
{
   public:
	virtual ~PixelClassifier() = default;

	/** For k in [0, count): out[k] = kFree or kDoubtfulFree when pixel
	 * `pixels[k]` (row * width + col) of the 8-bit BGR image starting at
	 * `bgr` is free floor, else kNotFree. */
	virtual void classify(const std::uint8_t* bgr, const std::int32_t* pixels, int count, std::uint8_t* out) const = 0;
};

}  // namespace omnirange
