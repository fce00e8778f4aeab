#pragma once
// Learning the edge bias (EdgeBias.h) from the laser: each hit that a laser
// ray confirms (within kEdgeBiasMaxDifference) is a sample of how far the
// obstacle's foot lies beyond a hit of that contrast.

#include <vector>

namespace omnirange
{
/** [m] laser/omnicam differences larger than this are another object, not a short hit. */
constexpr double kEdgeBiasMaxDifference = 0.3;

struct EdgeSample
{
	float contrast;  ///< the hit's contrast (Ray::edge_contrast)
	double difference;  ///< [m] laser - omnicam range at that bearing
};

/** Per contrast bin, the median difference of its samples when it has at
 * least `min_samples` of them with |difference| <= kEdgeBiasMaxDifference,
 * else 0; bins past the last learned one are dropped, so an empty result
 * learned nothing. */
std::vector<double> learnEdgeBias(const std::vector<EdgeSample>& samples, int min_samples);

}  // namespace omnirange
