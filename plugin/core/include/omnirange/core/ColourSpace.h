#pragma once
// Colour spaces and the binning of a pixel into one of n^3 histogram bins.
// A new colour space needs a name, an enumerator and a branch in toChannels().

#include <array>
#include <cstdint>
#include <string>

namespace omnirange
{
enum class ColourSpace : std::uint32_t
{
	RGB = 0,
	HSV = 1,  ///< hue over the full 0..255 range, saturation, value
	/** rg chromaticity (R and G over R+G+B) and log brightness: a change of
	 * exposure or of light's strength moves a colour along the brightness
	 * channel only, and by a fraction of a bin for modest changes. */
	Chroma = 2
};

std::string toString(ColourSpace s);
/** "RGB", "HSV" or "CHROMA" (any case); throws std::invalid_argument otherwise. */
ColourSpace colourSpaceFromString(const std::string& name);

/** 8-bit HSV with hue spanning 0..255 (not OpenCV's 0..179). */
void bgrToHsv(const std::uint8_t* bgr, std::uint8_t* hsv);

/** r = 255 R / (R+G+B), g = 255 G / (R+G+B), and 255 log(1 + mean) / log(256). */
void bgrToChroma(const std::uint8_t* bgr, std::uint8_t* chroma);

/** Maps a BGR pixel to its histogram bin, through per-channel lookup tables. */
class ColourBinner
{
   public:
	/** bins per channel must be in [1, 256]. */
	ColourBinner(ColourSpace space, int bins);

	ColourSpace space() const { return space_; }
	int binsPerChannel() const { return bins_; }
	std::uint32_t binCount() const
	{
		return static_cast<std::uint32_t>(bins_) * bins_ * bins_;
	}

	/** The bin that the colours of `bin` fall into in light `gain` times as
	 * strong (gain in (0, 1]: a shadow), taken at the bin's centre: RGB
	 * scales every channel, HSV its value, CHROMA its brightness (its
	 * chromaticity does not change). */
	std::uint32_t darkerBin(std::uint32_t bin, double gain) const;

	/** Bin index of a pixel stored as B, G, R bytes. */
	std::uint32_t binOf(const std::uint8_t* bgr) const
	{
		if (space_ == ColourSpace::RGB)
			return lut0_[bgr[2]] + lut1_[bgr[1]] + lut2_[bgr[0]];
		std::uint8_t c[3];
		if (space_ == ColourSpace::HSV)
			bgrToHsv(bgr, c);
		else
			bgrToChroma(bgr, c);
		return lut0_[c[0]] + lut1_[c[1]] + lut2_[c[2]];
	}

   private:
	ColourSpace space_;
	int bins_;
	// value -> bin * stride of channel 0, 1, 2 (R,G,B or H,S,V).
	std::array<std::uint32_t, 256> lut0_{}, lut1_{}, lut2_{};
};

}  // namespace omnirange
