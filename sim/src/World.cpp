// The world's geometry queries: materials by name, the spatial index and
// the ray cast that the renderer and the laser share.
#include "omnirange_sim/World.h"

#include <algorithm>
#include <cmath>

namespace omnirange::sim
{
int World::findMaterial(const std::string& n) const
{
	for (std::size_t i = 0; i < materials.size(); ++i)
		if (materials[i].name == n) return static_cast<int>(i);
	return -1;
}

void World::buildIndex(double cell)
{
	cell_ = cell;
	Vec2 lo = this->lo, hi = this->hi;
	for (const auto& s : solids)
	{
		lo = {std::min(lo.x, s.footprint.lo().x), std::min(lo.y, s.footprint.lo().y)};
		hi = {std::max(hi.x, s.footprint.hi().x), std::max(hi.y, s.footprint.hi().y)};
	}
	grid_lo_ = lo;
	nx_ = static_cast<int>(std::ceil((hi.x - lo.x) / cell_)) + 1;
	ny_ = static_cast<int>(std::ceil((hi.y - lo.y) / cell_)) + 1;
	grid_.assign(static_cast<std::size_t>(nx_) * ny_, {});
	for (std::size_t i = 0; i < solids.size(); ++i)
	{
		const auto& f = solids[i].footprint;
		const int x0 = static_cast<int>((f.lo().x - lo.x) / cell_);
		const int x1 = static_cast<int>((f.hi().x - lo.x) / cell_);
		const int y0 = static_cast<int>((f.lo().y - lo.y) / cell_);
		const int y1 = static_cast<int>((f.hi().y - lo.y) / cell_);
		for (int y = y0; y <= y1; ++y)
			for (int x = x0; x <= x1; ++x) grid_[y * nx_ + x].push_back(static_cast<int>(i));
	}
}

void World::castRay(const Vec2& o, const Vec2& d, double max_t,
					std::vector<SolidCrossing>& out) const
{
	out.clear();
	thread_local std::vector<int> candidates;
	candidates.clear();
	// March through the grid cells the ray visits (Amanatides-Woo).
	double px = (o.x - grid_lo_.x) / cell_, py = (o.y - grid_lo_.y) / cell_;
	int cx = static_cast<int>(std::floor(px)), cy = static_cast<int>(std::floor(py));
	const int sx = d.x > 0 ? 1 : -1, sy = d.y > 0 ? 1 : -1;
	const double inf = 1e30;
	const double dtx = d.x != 0 ? cell_ / std::abs(d.x) : inf;
	const double dty = d.y != 0 ? cell_ / std::abs(d.y) : inf;
	double tx = d.x != 0 ? ((sx > 0 ? (cx + 1 - px) : (px - cx)) * cell_) / std::abs(d.x) : inf;
	double ty = d.y != 0 ? ((sy > 0 ? (cy + 1 - py) : (py - cy)) * cell_) / std::abs(d.y) : inf;
	double t = 0;
	while (t <= max_t)
	{
		if (cx >= 0 && cy >= 0 && cx < nx_ && cy < ny_)
		{
			const auto& cellv = grid_[cy * nx_ + cx];
			candidates.insert(candidates.end(), cellv.begin(), cellv.end());
		}
		else if ((cx < 0 && sx < 0) || (cy < 0 && sy < 0) || (cx >= nx_ && sx > 0) ||
				 (cy >= ny_ && sy > 0))
			break;  // outside and moving away
		if (tx < ty)
			t = tx, tx += dtx, cx += sx;
		else
			t = ty, ty += dty, cy += sy;
	}
	std::sort(candidates.begin(), candidates.end());
	candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
	for (int i : candidates)
		if (const auto c = solids[i].footprint.intersect(o, d); c && c->t_in < max_t)
			out.push_back({*c, i});
	std::sort(out.begin(), out.end(), [](const SolidCrossing& a, const SolidCrossing& b) {
		return a.crossing.t_in < b.crossing.t_in;
	});
}

}  // namespace omnirange::sim
