#include "omnirange/core/EdgeBias.h"

#include "omnirange/core/BrightnessStep.h"

#include <algorithm>
#include <cmath>

namespace omnirange
{
float edgeContrast(const std::uint8_t* bgr, const std::int32_t* pixels, int hit)
{
	if (hit < kEdgeFloorFrom) return std::numeric_limits<float>::quiet_NaN();
	const auto brightness = [&](int k) {
		const std::uint8_t* px = bgr + 3 * static_cast<std::size_t>(pixels[k]);
		return px[0] + px[1] + px[2] + kDarkBrightnessOffset;
	};
	double floor = 0;
	for (int k = hit - kEdgeFloorFrom; k <= hit - kEdgeFloorTo; ++k) floor += brightness(k);
	floor /= kEdgeFloorFrom - kEdgeFloorTo + 1;
	return static_cast<float>(std::log(brightness(hit) / floor));
}

int edgeContrastBin(double contrast)
{
	if (!std::isfinite(contrast)) return -1;
	const double b = std::floor((contrast - kEdgeContrastFrom) / kEdgeContrastStep);
	return b >= 0 && b < kEdgeContrastBins ? static_cast<int>(b) : -1;
}

double edgeBiasAt(const std::vector<double>& bias, double contrast)
{
	const int b = edgeContrastBin(contrast);
	if (b < 0 || bias.empty()) return 0.0;
	// Linear between bin centres, so a hit whose contrast wavers across a
	// bin's edge from frame to frame does not jump by the bins' difference.
	const auto at = [&](int k) { return k < static_cast<int>(bias.size()) ? bias[k] : 0.0; };
	const double x = (contrast - kEdgeContrastFrom) / kEdgeContrastStep - 0.5;  // in bin centres
	const int k0 = std::clamp(static_cast<int>(std::floor(x)), 0, kEdgeContrastBins - 1);
	const int k1 = std::min(k0 + 1, kEdgeContrastBins - 1);
	const double t = std::clamp(x - k0, 0.0, 1.0);
	return (1 - t) * at(k0) + t * at(k1);
}

}  // namespace omnirange
