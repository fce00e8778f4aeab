#include "omnirange/train/EdgeBiasLearning.h"

#include "omnirange/core/EdgeBias.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace omnirange
{
std::vector<double> learnEdgeBias(const std::vector<EdgeSample>& samples, int min_samples)
{
	if (min_samples < 1) throw std::invalid_argument("learnEdgeBias: min_samples must be >= 1");
	std::vector<std::vector<double>> bins(kEdgeContrastBins);
	for (const EdgeSample& s : samples)
		if (const int b = edgeContrastBin(s.contrast); b >= 0 && std::abs(s.difference) <= kEdgeBiasMaxDifference)
			bins[b].push_back(s.difference);
	std::vector<double> bias(kEdgeContrastBins, 0.0);
	int last = -1;
	for (int b = 0; b < kEdgeContrastBins; ++b)
	{
		std::vector<double>& d = bins[b];
		if (static_cast<int>(d.size()) < min_samples) continue;
		// The median: a hit on another object than the laser's is an outlier here.
		std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
		bias[b] = d[d.size() / 2];
		last = b;
	}
	bias.resize(last + 1);
	return bias;
}

}  // namespace omnirange
