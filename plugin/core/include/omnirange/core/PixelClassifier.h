#pragma once
// The seam between the polar scanner and a free-space model (paper §III-A):
// the scanner asks for the pixels of one scanline in short runs, so a model
// is called once per run rather than once per pixel, and pixels beyond the
// hit search's decision are never classified. Another model (two-class,
// other features) plugs in by implementing classify().

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace omnirange
{
/** What classify() writes per pixel. A model that knows no doubt writes
 * only kNotFree and kFree, and every free pixel it sees is sure floor. */
inline constexpr std::uint8_t kNotFree = 0;
inline constexpr std::uint8_t kFree = 1;  ///< free, and the colour is sure floor
inline constexpr std::uint8_t kDoubtfulFree = 3;  ///< free, but a colour the floor rarely shows

/** The smallest box of an image's pixels that holds a set of pixel indices
 * (row * width + col): what a stage reads of an image, so that a decoder may
 * decode only that (ObservationImage.h). */
struct PixelBox
{
	int left{std::numeric_limits<int>::max()}, top{std::numeric_limits<int>::max()};
	int right{-1}, bottom{-1};  ///< inclusive; the box is empty while right < left

	void add(const std::vector<std::int32_t>& pixels, int width)
	{
		for (const std::int32_t p : pixels)
		{
			const int row = p / width, col = p % width;
			left = std::min(left, col), right = std::max(right, col);
			top = std::min(top, row), bottom = std::max(bottom, row);
		}
	}
	void add(const PixelBox& b)
	{
		left = std::min(left, b.left), right = std::max(right, b.right);
		top = std::min(top, b.top), bottom = std::max(bottom, b.bottom);
	}
	bool empty() const { return right < left; }
};

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
