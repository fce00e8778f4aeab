#pragma once
// 2D geometry of the simulated world: every solid is a vertical prism whose
// footprint is a convex polygon or a circle.

#include <optional>
#include <vector>

namespace omnirange::sim
{
struct Vec2
{
	double x{0}, y{0};
	Vec2 operator+(const Vec2& o) const { return {x + o.x, y + o.y}; }
	Vec2 operator-(const Vec2& o) const { return {x - o.x, y - o.y}; }
	Vec2 operator*(double s) const { return {x * s, y * s}; }
	double dot(const Vec2& o) const { return x * o.x + y * o.y; }
	double cross(const Vec2& o) const { return x * o.y - y * o.x; }
	double norm() const;
};

/** Where a ray (origin + t * unit direction) crosses a footprint. */
struct Crossing
{
	double t_in{0};  ///< [m] entry distance (0 if the origin is inside)
	double t_out{0};  ///< [m] exit distance
	Vec2 normal;  ///< outward unit normal at the entry
};

class Footprint
{
   public:
	/** A convex polygon; vertices in either winding. */
	static Footprint polygon(std::vector<Vec2> vertices);
	/** An oriented rectangle: centre, size along its own x (w) and y (d), yaw [rad]. */
	static Footprint box(Vec2 centre, double w, double d, double yaw);
	static Footprint circle(Vec2 centre, double radius);

	bool isCircle() const { return radius_ > 0; }
	const std::vector<Vec2>& vertices() const { return v_; }  ///< CCW; empty for circles
	Vec2 centre() const { return c_; }
	double radius() const { return radius_; }

	/** Axis-aligned bounds. */
	Vec2 lo() const { return lo_; }
	Vec2 hi() const { return hi_; }

	/** The ray's crossing with t_out > 0, or nothing. `dir` is a unit vector. */
	std::optional<Crossing> intersect(const Vec2& origin, const Vec2& dir) const;
	/** Distance from p to the footprint (0 inside). */
	double distance(const Vec2& p) const;
	/** Smallest distance between the segment a-b and the footprint. */
	double distanceToSegment(const Vec2& a, const Vec2& b) const;
	/** The polygon itself, or a 32-gon for a circle. */
	std::vector<Vec2> outline() const;

   private:
	std::vector<Vec2> v_;
	Vec2 c_;
	double radius_{0};
	Vec2 lo_, hi_;
	void computeBounds();
};

}  // namespace omnirange::sim
