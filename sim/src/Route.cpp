#include "omnirange_sim/Route.h"

#include <omnirange/config/OptionsTable.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace omnirange::sim
{
namespace
{
double wrap(double a) { return std::atan2(std::sin(a), std::cos(a)); }
}  // namespace

Route loadRoute(const std::string& path)
{
	requireRegularFile(path, "route file");
	std::ifstream f(path);
	if (!f) throw std::runtime_error(path + ": cannot open route file");
	Route r;
	r.file = path;
	std::string raw;
	for (int line = 1; readCappedLine(f, raw, path, line, "route file"); ++line)
	{
		const auto fail = [&](const std::string& why) {
			return std::runtime_error(path + ":" + std::to_string(line) + ": " + why);
		};
		std::istringstream in(raw.substr(0, raw.find('#')));
		std::vector<std::string> tok;
		for (std::string t; in >> t;) tok.push_back(t);
		if (tok.empty()) continue;
		double xy[2];
		for (int i = 0; i < 2 && tok.size() == 2; ++i)
		{
			char* end = nullptr;
			xy[i] = std::strtod(tok[i].c_str(), &end);
			if (*end != '\0' || !std::isfinite(xy[i])) tok.clear();
		}
		if (tok.size() != 2) throw fail("expected 'x y' in metres");
		const Vec2 p{xy[0], xy[1]};
		if (!(std::abs(p.x) <= kMaxWorldCoordinate && std::abs(p.y) <= kMaxWorldCoordinate))
			throw fail("a waypoint beyond " + std::to_string(static_cast<int>(kMaxWorldCoordinate)) + " m from the origin");
		if (!r.waypoints.empty() && (p - r.waypoints.back()).norm() < 1e-6)
			throw fail("waypoint repeats the previous one");
		r.waypoints.push_back(p);
		r.lines.push_back(line);
	}
	if (r.waypoints.size() < 2) throw std::runtime_error(path + ": a route needs at least 2 waypoints");
	return r;
}

void checkRouteClear(const Route& route, const World& world, double clearance, double robot_height)
{
	// The true map covers the world's bounds: a route past them is mapped nowhere.
	for (std::size_t i = 0; i < route.waypoints.size(); ++i)
	{
		const Vec2& p = route.waypoints[i];
		if (world.hi.x > world.lo.x && !(p.x >= world.lo.x && p.x <= world.hi.x && p.y >= world.lo.y && p.y <= world.hi.y))
		{
			std::ostringstream m;
			m << route.file << ":" << route.lines[i] << ": the waypoint (" << p.x << ", " << p.y
			  << ") lies outside the bounds of " << world.file << " (x " << world.lo.x << " to " << world.hi.x << ", y "
			  << world.lo.y << " to " << world.hi.y << ")";
			throw std::runtime_error(m.str());
		}
	}
	for (std::size_t i = 0; i + 1 < route.waypoints.size(); ++i)
		for (const auto& s : world.solids)
		{
			if (s.z0 >= robot_height) continue;  // the robot drives under it
			const double d = s.footprint.distanceToSegment(route.waypoints[i], route.waypoints[i + 1]);
			if (d < clearance)
			{
				std::ostringstream m;
				m << route.file << ":" << route.lines[i + 1] << ": the leg to this waypoint passes "
				  << (d == 0 ? "through" : "within " + formatDouble(std::round(d * 1000) / 1000) + " m of")
				  << " the solid of " << world.file << ":" << s.line << " (clearance needed "
				  << clearance << " m)";
				throw std::runtime_error(m.str());
			}
		}
}

std::vector<Pose2> sampleTrajectory(const Route& route, double speed, double turn_rate, double dt, int max_frames)
{
	if (!(speed > 0) || !(turn_rate > 0) || !(dt > 0))
		throw std::invalid_argument("speed, turn_rate and the frame period must be > 0");
	// Build the motion as a list of segments (drive or turn) with durations.
	struct Seg
	{
		Pose2 start;
		double dist, turn, duration;
	};
	std::vector<Seg> segs;
	const auto& w = route.waypoints;
	double yaw = std::atan2(w[1].y - w[0].y, w[1].x - w[0].x);
	for (std::size_t i = 0; i + 1 < w.size(); ++i)
	{
		const double heading = std::atan2(w[i + 1].y - w[i].y, w[i + 1].x - w[i].x);
		const double turn = wrap(heading - yaw);
		if (std::abs(turn) > 1e-9) segs.push_back({{w[i].x, w[i].y, yaw}, 0, turn, std::abs(turn) / turn_rate});
		yaw = heading;
		const double dist = (w[i + 1] - w[i]).norm();
		segs.push_back({{w[i].x, w[i].y, yaw}, dist, 0, dist / speed});
	}
	double total = 0;
	for (const auto& s : segs) total += s.duration;
	const double frames = std::floor(total / dt) + 1;
	if (frames > kMaxRouteFrames && (max_frames <= 0 || max_frames > kMaxRouteFrames))
	{
		std::ostringstream m;
		m << "the route is " << std::llround(std::min(frames, 1e18)) << " frames long (" << total << " s at "
		  << 1.0 / dt << " Hz); at most " << kMaxRouteFrames << " are written: stop sooner with max_frames (-n)";
		throw std::runtime_error(m.str());
	}
	std::vector<Pose2> out;
	double t = 0, seg_start = 0;
	std::size_t k = 0;
	for (; max_frames <= 0 || static_cast<int>(out.size()) < max_frames; t += dt)
	{
		while (k < segs.size() && t > seg_start + segs[k].duration) seg_start += segs[k++].duration;
		if (k == segs.size()) break;
		const Seg& s = segs[k];
		const double f = s.duration > 0 ? (t - seg_start) / s.duration : 1.0;
		out.push_back({s.start.x + std::cos(s.start.yaw) * s.dist * f,
					   s.start.y + std::sin(s.start.yaw) * s.dist * f, wrap(s.start.yaw + s.turn * f)});
	}
	return out;
}

}  // namespace omnirange::sim
