#include "omnirange/core/ColourSpace.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <cctype>
#include <stdexcept>

namespace omnirange
{
std::string toString(ColourSpace s)
{
	switch (s)
	{
		case ColourSpace::RGB: return "RGB";
		case ColourSpace::HSV: return "HSV";
		case ColourSpace::Chroma: return "CHROMA";
	}
	throw std::logic_error("unknown ColourSpace");
}

ColourSpace colourSpaceFromString(const std::string& name)
{
	std::string n = name;
	std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) {
		return static_cast<char>(std::toupper(c));
	});
	if (n == "RGB") return ColourSpace::RGB;
	if (n == "HSV") return ColourSpace::HSV;
	if (n == "CHROMA") return ColourSpace::Chroma;
	throw std::invalid_argument("colour space must be RGB, HSV or CHROMA, not '" + name + "'");
}

void bgrToHsv(const std::uint8_t* bgr, std::uint8_t* hsv)
{
	const int b = bgr[0], g = bgr[1], r = bgr[2];
	const int v = std::max({r, g, b});
	const int delta = v - std::min({r, g, b});
	hsv[2] = static_cast<std::uint8_t>(v);
	hsv[1] = static_cast<std::uint8_t>(v == 0 ? 0 : (255 * delta) / v);
	if (delta == 0)
	{
		hsv[0] = 0;
		return;
	}
	// Hue in sixths of the circle, each sixth 256/6 wide.
	int h6;  // hue * 6 * delta, in units of a sixth
	if (v == r)
		h6 = (g - b) + (g < b ? 6 * delta : 0);
	else if (v == g)
		h6 = (b - r) + 2 * delta;
	else
		h6 = (r - g) + 4 * delta;
	hsv[0] = static_cast<std::uint8_t>((h6 * 256 / (6 * delta)) & 0xFF);
}

namespace
{
/** 255 log(1 + m) / log(256) for every mean brightness m, and 255 * 256 / s
 * for every channel sum s (so a chromaticity is one multiply and a shift). */
struct ChromaTables
{
	std::array<std::uint8_t, 256> log_mean{};
	std::array<std::uint32_t, 766> inverse_sum{};
	ChromaTables()
	{
		for (int m = 0; m < 256; ++m)
			log_mean[m] = static_cast<std::uint8_t>(std::lround(255.0 * std::log1p(m) / std::log(256.0)));
		for (int s = 1; s < 766; ++s) inverse_sum[s] = static_cast<std::uint32_t>(255u * 65536u / s);
	}
};
const ChromaTables& chromaTables()
{
	static const ChromaTables t;
	return t;
}
}  // namespace

void bgrToChroma(const std::uint8_t* bgr, std::uint8_t* c)
{
	const auto& t = chromaTables();
	const int sum = bgr[0] + bgr[1] + bgr[2];
	if (sum == 0)
	{
		c[0] = c[1] = 85, c[2] = 0;  // black: grey chromaticity, no brightness
		return;
	}
	c[0] = static_cast<std::uint8_t>(std::min<std::uint32_t>(255, (bgr[2] * t.inverse_sum[sum]) >> 16));
	c[1] = static_cast<std::uint8_t>(std::min<std::uint32_t>(255, (bgr[1] * t.inverse_sum[sum]) >> 16));
	c[2] = t.log_mean[sum / 3];
}

ColourBinner::ColourBinner(ColourSpace space, int bins)
	: space_(space), bins_(bins)
{
	if (bins < 1 || bins > 256)
		throw std::invalid_argument(
			"histogram bins per channel must be in [1, 256], not " +
			std::to_string(bins));
	const std::uint32_t n = static_cast<std::uint32_t>(bins);
	for (std::uint32_t x = 0; x < 256; ++x)
	{
		const std::uint32_t bin = x * n / 256;
		lut0_[x] = bin * n * n;
		lut1_[x] = bin * n;
		lut2_[x] = bin;
	}
}

std::uint32_t ColourBinner::darkerBin(std::uint32_t bin, double gain) const
{
	const std::uint32_t n = static_cast<std::uint32_t>(bins_);
	std::uint32_t c[3] = {bin / (n * n), (bin / n) % n, bin % n};
	// A channel value at its bin's centre, darkened, back into a bin.
	const auto binOfValue = [n](double v) {
		return static_cast<std::uint32_t>(std::clamp(v, 0.0, 255.0) * n / 256.0);
	};
	const auto darker = [&](std::uint32_t k) { return binOfValue((k + 0.5) * 256.0 / n * gain); };
	if (space_ == ColourSpace::RGB)
		for (auto& k : c) k = darker(k);
	else if (space_ == ColourSpace::HSV)
		c[2] = darker(c[2]);
	else
	{
		// Brightness channel: 255 log(1 + mean) / log(256) (bgrToChroma).
		const double v = (c[2] + 0.5) * 256.0 / n, log256 = std::log(256.0);
		const double mean = std::expm1(v / 255.0 * log256);
		c[2] = binOfValue(255.0 * std::log1p(mean * gain) / log256);
	}
	return (c[0] * n + c[1]) * n + c[2];
}

}  // namespace omnirange
