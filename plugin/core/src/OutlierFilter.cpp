#include "omnirange/core/OutlierFilter.h"

#include "omnirange/config/OptionsTable.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace omnirange
{
std::string toString(OutlierFilterKind k)
{
	switch (k)
	{
		case OutlierFilterKind::None: return "none";
		case OutlierFilterKind::Spike: return "spike";
	}
	throw std::logic_error("unknown OutlierFilterKind");
}

OutlierFilterKind outlierFilterKindFromString(const std::string& name)
{
	if (name == "none") return OutlierFilterKind::None;
	if (name == "spike") return OutlierFilterKind::Spike;
	throw std::invalid_argument("outlier_filter must be 'none' or 'spike', not '" + name + "'");
}

const OptionsTable<OutlierFilterParams>& OutlierFilterParams::table()
{
	using P = OutlierFilterParams;
	static const auto t = OptionsTable<P>()
		.addEnum("outlier_filter", "spike rejects rays that disagree with both neighbours; none keeps all",
				 [](P& p) -> auto& { return p.outlier_filter; }, outlierFilterKindFromString,
				 {OutlierFilterKind::None, OutlierFilterKind::Spike})
		.add("outlier_max_width", "rays", "widest run of rays the spike filter rejects",
			 [](P& p) -> auto& { return p.outlier_max_width; })
		.within(Range::closed(1, 100))
		.add("outlier_abs_tol", "m",
			 "two ranges agree when they differ by at most outlier_abs_tol + outlier_rel_tol * range",
			 [](P& p) -> auto& { return p.outlier_abs_tol; })
		.within(Range::atLeast(0))
		.add("outlier_rel_tol", "-", "relative part of that tolerance", [](P& p) -> auto& { return p.outlier_rel_tol; })
		.within(Range::atLeast(0));
	return t;
}

void OutlierFilterParams::validate() const
{
	table().requireRanges(*this);
}

int rejectOutliers(std::vector<Ray>& rays, const OutlierFilterParams& p)
{
	const int n = static_cast<int>(rays.size());
	if (p.outlier_filter == OutlierFilterKind::None || n < p.outlier_max_width + 2) return 0;

	const auto agree = [&](float a, float b) {
		return std::abs(a - b) <= p.outlier_abs_tol + p.outlier_rel_tol * std::min(a, b);
	};
	const auto at = [&](int i) -> const Ray& { return rays[(i % n + n) % n]; };

	// Decide on the unfiltered scan, then mark, so one rejection does not
	// change what its neighbours are compared against.
	std::vector<char> reject(n, 0);
	for (int start = 0; start < n; ++start)
		for (int width = 1; width <= p.outlier_max_width; ++width)
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
