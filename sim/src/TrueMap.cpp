#include "omnirange_sim/Simulator.h"

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace omnirange::sim
{
mrpt::maps::COccupancyGridMap2D trueMap(const World& world, double res, double below)
{
	mrpt::maps::COccupancyGridMap2D grid(
		static_cast<float>(world.lo.x), static_cast<float>(world.hi.x),
		static_cast<float>(world.lo.y), static_cast<float>(world.hi.y), static_cast<float>(res));
	const int w = static_cast<int>(grid.getSizeX()), h = static_cast<int>(grid.getSizeY());
	// Rasterise with sub-cell precision (8x) so thin solids still mark cells.
	constexpr int kShift = 3;
	cv::Mat occ(h, w, CV_8UC1, cv::Scalar(0));
	for (const auto& s : world.solids)
	{
		if (s.z0 >= below) continue;
		std::vector<cv::Point> pts;
		for (const auto& q : s.footprint.outline())
			pts.emplace_back(static_cast<int>(std::lround((q.x - grid.getXMin()) / res * (1 << kShift) - 0.5 * (1 << kShift))),
							 static_cast<int>(std::lround((q.y - grid.getYMin()) / res * (1 << kShift) - 0.5 * (1 << kShift))));
		cv::fillConvexPoly(occ, pts, cv::Scalar(255), cv::LINE_8, kShift);
	}
	for (int y = 0; y < h; ++y)
		for (int x = 0; x < w; ++x)
			grid.setCell(x, y, occ.at<std::uint8_t>(y, x) ? 0.0f : 1.0f);  // getCell(): P(free)
	return grid;
}

}  // namespace omnirange::sim
