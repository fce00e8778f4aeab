#include "omnirange/core/WallFit.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace omnirange
{
const OptionsTable<WallFitParams>& WallFitParams::table()
{
	using P = WallFitParams;
	static const auto t = OptionsTable<P>()
		.add("wall_fit", "bool",
			 "thin walls: move hits that lie on one straight wall onto a line fitted to them, weighted by "
			 "each range's uncertainty from the mirror's geometry",
			 [](P& p) -> auto& { return p.wall_fit; })
		.add("wall_fit_min_rays", "rays", "with wall_fit: the shortest run of hits fitted with a line",
			 [](P& p) -> auto& { return p.wall_fit_min_rays; })
		.within(Range::closed(3, 10000))
		.add("wall_fit_tolerance", "sigma",
			 "with wall_fit: a hit is on the line when its range is within this many of its uncertainties",
			 [](P& p) -> auto& { return p.wall_fit_tolerance; })
		.within(Range::openLow(0, 100))
		.add("boundary_sigma", "px",
			 "the floor boundary's uncertainty in the image, which the mirror turns into each range's",
			 [](P& p) -> auto& { return p.boundary_sigma; })
		.within(Range::openLow(0, 10));
	return t;
}

void WallFitParams::validate() const
{
	table().requireRanges(*this);
}

double rangeSigma(const OmniCameraModel& camera, double rho, double boundary_sigma)
{
	const double nearer = camera.distanceFromRho(std::max(0.0, rho - 0.5));
	const double farther = camera.distanceFromRho(rho + 0.5);
	if (!std::isfinite(farther)) return std::numeric_limits<double>::infinity();
	return boundary_sigma * (farther - nearer);
}

namespace
{
struct Point
{
	double x, y, w;  // position [m] and weight 1 / sigma^2
	double cos_b, sin_b, range, sigma;  // the bearing's cosine and sine: each split of a run uses them again
};

/** A line n . p = d (|n| = 1) through weighted points [a, b). */
struct Line
{
	double nx{0}, ny{0}, d{0};
	bool ok{false};
};

Line fitLine(const std::vector<Point>& pts, int a, int b)
{
	double sw = 0, cx = 0, cy = 0;
	for (int i = a; i < b; ++i) sw += pts[i].w, cx += pts[i].w * pts[i].x, cy += pts[i].w * pts[i].y;
	if (!(sw > 0)) return {};
	cx /= sw, cy /= sw;
	double sxx = 0, sxy = 0, syy = 0;
	for (int i = a; i < b; ++i)
	{
		const double dx = pts[i].x - cx, dy = pts[i].y - cy;
		sxx += pts[i].w * dx * dx, sxy += pts[i].w * dx * dy, syy += pts[i].w * dy * dy;
	}
	// The normal is the scatter's direction of least spread.
	const double angle = 0.5 * std::atan2(2 * sxy, sxx - syy);  // of the most spread
	Line l;
	l.nx = -std::sin(angle), l.ny = std::cos(angle);
	l.d = l.nx * cx + l.ny * cy;
	l.ok = true;
	return l;
}

/** Where the ray of `p` meets the line, or -1 when it grazes it or meets it
 * behind the sensor. */
double rangeOnLine(const Line& l, const Point& p)
{
	const double c = l.nx * p.cos_b + l.ny * p.sin_b;
	if (std::abs(c) < 0.1) return -1;  // within 6 degrees of running along it
	const double r = l.d / c;
	return r > 0 ? r : -1;
}

/** The point of (a, b - 1) farthest from the chord between a and b - 1:
 * where a run that is not straight turns (split-and-merge's corner). */
int farthestFromChord(const std::vector<Point>& pts, int a, int b)
{
	const double dx = pts[b - 1].x - pts[a].x, dy = pts[b - 1].y - pts[a].y;
	const double len = std::hypot(dx, dy);
	int k = a + 1;
	double best = -1;
	for (int i = a + 1; i < b - 1; ++i)
	{
		const double ex = pts[i].x - pts[a].x, ey = pts[i].y - pts[a].y;
		const double dist = len > 1e-9 ? std::abs(ex * dy - ey * dx) / len : std::hypot(ex, ey);
		if (dist > best) best = dist, k = i;
	}
	return k;
}

/** Fits [a, b) of one run of hits, splitting it where it is not straight. */
void fitRun(const std::vector<Point>& pts, int a, int b, const WallFitParams& p, std::vector<double>& fitted)
{
	if (b - a < p.wall_fit_min_rays) return;
	const Line l = fitLine(pts, a, b);
	if (!l.ok) return;
	double worst_z = -1;
	std::vector<double> on(b - a, -1);
	for (int i = a; i < b; ++i)
	{
		on[i - a] = rangeOnLine(l, pts[i]);
		const double z = on[i - a] < 0 ? 1e9 : std::abs(on[i - a] - pts[i].range) / pts[i].sigma;
		worst_z = std::max(worst_z, z);
	}
	if (worst_z <= p.wall_fit_tolerance)
	{
		for (int i = a; i < b; ++i) fitted[i] = on[i - a];
		return;
	}
	// Not one wall: split where the run turns, the corner in both halves
	// (a stray hit ends up in pieces too short to fit, left as measured).
	const int k = farthestFromChord(pts, a, b);
	fitRun(pts, a, k + 1, p, fitted);
	fitRun(pts, k, b, p, fitted);
}
}  // namespace

int fitWalls(std::vector<Ray>& rays, const OmniCameraModel& camera, const WallFitParams& p, double min_range,
			 double max_range)
{
	if (!p.wall_fit) return 0;
	p.validate();
	const int n = static_cast<int>(rays.size());
	// Start the walk just after a ray that is not a hit, so no run is cut by
	// the scan's wrap; a scan of hits all round starts at its largest jump
	// in range (a corner or a step, where a run would be split anyway).
	int start = -1;
	for (int i = 0; i < n; ++i)
		if (rays[i].status != RayStatus::Hit) start = (i + 1) % n;
	if (start < 0)
	{
		start = 0;
		double jump = -1;
		for (int i = 0; i < n; ++i)
		{
			const double d = std::abs(rays[i].range - rays[(i + n - 1) % n].range);
			if (d > jump) jump = d, start = i;
		}
	}
	int moved = 0;
	std::vector<Point> run;
	std::vector<int> index;
	const auto flush = [&]() {
		std::vector<double> fitted(run.size(), -1);
		fitRun(run, 0, static_cast<int>(run.size()), p, fitted);
		for (std::size_t k = 0; k < run.size(); ++k)
			if (fitted[k] >= min_range && fitted[k] <= max_range)
				rays[index[k]].range = static_cast<float>(fitted[k]), ++moved;
		run.clear(), index.clear();
	};
	for (int k = 0; k < n; ++k)
	{
		const int i = (start + k) % n;
		const Ray& r = rays[i];
		const double sigma = r.status == RayStatus::Hit ? rangeSigma(camera, r.hit_rho, p.boundary_sigma) : 0;
		if (r.status != RayStatus::Hit || !std::isfinite(sigma) || !(sigma > 0))
		{
			flush();
			continue;
		}
		const double c = std::cos(r.bearing), s = std::sin(r.bearing);
		run.push_back({r.range * c, r.range * s, 1 / (sigma * sigma), c, s, r.range, sigma});
		index.push_back(i);
	}
	flush();
	return moved;
}

}  // namespace omnirange
