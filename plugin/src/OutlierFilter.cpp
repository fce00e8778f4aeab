#include "omnirange/OutlierFilter.h"

#include "omnirange/Config.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace omnirange
{
std::string toString(OutlierFilterKind k)
{
	return k == OutlierFilterKind::None ? "none" : "spike";
}

OutlierFilterKind outlierFilterKindFromString(const std::string& name)
{
	if (name == "none") return OutlierFilterKind::None;
	if (name == "spike") return OutlierFilterKind::Spike;
	throw std::invalid_argument(
		"outlier_filter must be 'none' or 'spike', not '" + name + "'");
}

void OutlierFilterParams::validate() const
{
	requireParam(max_width >= 1, "outlier filter", "outlier_max_width must be >= 1");
	requireParam(
		abs_tol >= 0 && rel_tol >= 0, "outlier filter",
		"outlier_abs_tol and outlier_rel_tol must be >= 0");
}

int rejectOutliers(std::vector<Ray>& rays, const OutlierFilterParams& p)
{
	const int n = static_cast<int>(rays.size());
	if (p.kind == OutlierFilterKind::None || n < p.max_width + 2) return 0;

	const auto agree = [&](float a, float b) {
		return std::abs(a - b) <= p.abs_tol + p.rel_tol * std::min(a, b);
	};
	const auto at = [&](int i) -> const Ray& { return rays[(i % n + n) % n]; };

	// Decide on the unfiltered scan, then mark, so one rejection does not
	// change what its neighbours are compared against.
	std::vector<char> reject(n, 0);
	for (int start = 0; start < n; ++start)
		for (int width = 1; width <= p.max_width; ++width)
		{
			const Ray& left = at(start - 1);
			const Ray& right = at(start + width);
			if (!agree(left.range, right.range)) continue;
			bool spike = true;
			for (int k = start; k < start + width && spike; ++k)
				spike = at(k).status == RayStatus::Hit &&
					!agree(at(k).range, left.range) && !agree(at(k).range, right.range);
			if (!spike) continue;
			for (int k = start; k < start + width; ++k) reject[k % n] = 1;
			break;
		}
	int marked = 0;
	for (int i = 0; i < n; ++i)
		if (reject[i]) rays[i].status = RayStatus::Outlier, ++marked;
	return marked;
}

}  // namespace omnirange
