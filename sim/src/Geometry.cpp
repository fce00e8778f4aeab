#include "omnirange_sim/Geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace omnirange::sim
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b)
{
	const Vec2 ab = b - a;
	const double len2 = ab.dot(ab);
	const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
	return (p - (a + ab * t)).norm();
}

bool segmentsCross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d)
{
	const double d1 = (b - a).cross(c - a), d2 = (b - a).cross(d - a);
	const double d3 = (d - c).cross(a - c), d4 = (d - c).cross(b - c);
	return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}
}  // namespace

double Vec2::norm() const { return std::hypot(x, y); }

Footprint Footprint::polygon(std::vector<Vec2> v)
{
	if (v.size() < 3) throw std::invalid_argument("a polygon needs at least 3 vertices");
	double area2 = 0;
	for (std::size_t i = 0; i < v.size(); ++i) area2 += v[i].cross(v[(i + 1) % v.size()]);
	if (std::abs(area2) < 1e-12) throw std::invalid_argument("a polygon has no area");
	if (area2 < 0) std::reverse(v.begin(), v.end());
	for (std::size_t i = 0; i < v.size(); ++i)
	{
		const Vec2 e1 = v[(i + 1) % v.size()] - v[i];
		const Vec2 e2 = v[(i + 2) % v.size()] - v[(i + 1) % v.size()];
		if (e1.cross(e2) < -1e-12) throw std::invalid_argument("a polygon is not convex");
	}
	Footprint f;
	f.v_ = std::move(v);
	for (const auto& p : f.v_) f.c_ = f.c_ + p * (1.0 / f.v_.size());
	f.computeBounds();
	return f;
}

Footprint Footprint::box(Vec2 c, double w, double d, double yaw)
{
	if (!(w > 0) || !(d > 0)) throw std::invalid_argument("a box needs w > 0 and d > 0");
	const Vec2 ax{std::cos(yaw) * 0.5 * w, std::sin(yaw) * 0.5 * w};
	const Vec2 ay{-std::sin(yaw) * 0.5 * d, std::cos(yaw) * 0.5 * d};
	return polygon({c - ax - ay, c + ax - ay, c + ax + ay, c - ax + ay});
}

Footprint Footprint::circle(Vec2 c, double r)
{
	if (!(r > 0)) throw std::invalid_argument("a circle needs a radius > 0");
	Footprint f;
	f.c_ = c;
	f.radius_ = r;
	f.computeBounds();
	return f;
}

void Footprint::computeBounds()
{
	if (isCircle())
	{
		lo_ = {c_.x - radius_, c_.y - radius_};
		hi_ = {c_.x + radius_, c_.y + radius_};
		return;
	}
	lo_ = hi_ = v_[0];
	for (const auto& p : v_)
	{
		lo_ = {std::min(lo_.x, p.x), std::min(lo_.y, p.y)};
		hi_ = {std::max(hi_.x, p.x), std::max(hi_.y, p.y)};
	}
}

std::optional<Crossing> Footprint::intersect(const Vec2& o, const Vec2& dir) const
{
	if (isCircle())
	{
		const Vec2 oc = o - c_;
		const double b = oc.dot(dir), c = oc.dot(oc) - radius_ * radius_;
		const double disc = b * b - c;
		if (disc <= 0) return std::nullopt;
		const double s = std::sqrt(disc);
		const double t0 = -b - s, t1 = -b + s;
		if (t1 <= 0) return std::nullopt;
		const double tin = std::max(t0, 0.0);
		const Vec2 p = o + dir * tin - c_;
		return Crossing{tin, t1, p * (1.0 / std::max(p.norm(), 1e-12))};
	}
	// Cyrus-Beck clipping against the CCW polygon's edges.
	double tin = -std::numeric_limits<double>::infinity();
	double tout = std::numeric_limits<double>::infinity();
	Vec2 nin;
	for (std::size_t i = 0; i < v_.size(); ++i)
	{
		const Vec2 a = v_[i], e = v_[(i + 1) % v_.size()] - a;
		const Vec2 n = Vec2{e.y, -e.x} * (1.0 / e.norm());  // outward for CCW
		const double denom = n.dot(dir), dist = n.dot(a - o);
		if (std::abs(denom) < 1e-15)
		{
			if (dist < 0) return std::nullopt;  // parallel and outside
			continue;
		}
		const double t = dist / denom;
		if (denom < 0)
		{
			if (t > tin) tin = t, nin = n;
		}
		else
			tout = std::min(tout, t);
	}
	if (tin > tout || tout <= 0) return std::nullopt;
	return Crossing{std::max(tin, 0.0), tout, nin};
}

double Footprint::distance(const Vec2& p) const
{
	if (isCircle()) return std::max(0.0, (p - c_).norm() - radius_);
	bool inside = true;
	double best = std::numeric_limits<double>::infinity();
	for (std::size_t i = 0; i < v_.size(); ++i)
	{
		const Vec2 a = v_[i], b = v_[(i + 1) % v_.size()];
		if ((b - a).cross(p - a) < 0) inside = false;
		best = std::min(best, pointSegmentDistance(p, a, b));
	}
	return inside ? 0.0 : best;
}

double Footprint::distanceToSegment(const Vec2& a, const Vec2& b) const
{
	if (isCircle()) return std::max(0.0, pointSegmentDistance(c_, a, b) - radius_);
	if (distance(a) == 0 || distance(b) == 0) return 0;
	double best = std::numeric_limits<double>::infinity();
	for (std::size_t i = 0; i < v_.size(); ++i)
	{
		const Vec2 c = v_[i], d = v_[(i + 1) % v_.size()];
		if (segmentsCross(a, b, c, d)) return 0;
		best = std::min({best, pointSegmentDistance(c, a, b), pointSegmentDistance(a, c, d),
						 pointSegmentDistance(b, c, d)});
	}
	return best;
}

std::vector<Vec2> Footprint::outline() const
{
	if (!isCircle()) return v_;
	std::vector<Vec2> out;
	for (int i = 0; i < 32; ++i)
		out.push_back(c_ + Vec2{std::cos(2 * kPi * i / 32), std::sin(2 * kPi * i / 32)} * radius_);
	return out;
}

}  // namespace omnirange::sim
