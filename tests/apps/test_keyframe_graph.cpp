// Loop closure over the guarded matcher's keyframes: a drive round a ring
// corridor whose estimate drifts, with the scans drawn where the robot truly
// was, must come back to the truth when the loop closes; the gates must hold.
#include <omnirange_slam/GuardedIcp.h>
#include <omnirange_slam/KeyframeGraph.h>
#include <omnirange_eval/Trajectory.h>

#include "../common/DrawnScans.h"

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace omnirange;
using namespace omnirange::eval;
using namespace omnirange::slam;
using namespace omnirange::test;

namespace
{
// A ring corridor 2.5 m wide round a 6 x 3 m block, in a 12 x 8 m hall, with
// a pillar and a niche so that no two places look alike.
const std::vector<Wall> kRing{
	{-6, -4, 6, -4}, {6, -4, 6, 4}, {6, 4, -6, 4}, {-6, 4, -6, -4},  // the hall
	{-3, -1.5, 3, -1.5}, {3, -1.5, 3, 1.5}, {3, 1.5, -3, 1.5}, {-3, 1.5, -3, -1.5},  // the block
	{-1.2, -3.4, -0.8, -3.4}, {-0.8, -3.4, -0.8, -3.0}, {-0.8, -3.0, -1.2, -3.0}, {-1.2, -3.0, -1.2, -3.4},  // a pillar
	{4.0, 4, 4.0, 3.3}, {4.0, 3.3, 5.0, 3.3}, {5.0, 3.3, 5.0, 4}};  // a cupboard

// The true path round the ring, counter-clockwise from its bottom left
// corner, one keyframe every 0.5 m: 59 keyframes, the last one back at the
// first.
std::vector<CPose2D> ringPath()
{
	const std::vector<std::pair<double, double>> corners{{-4.5, -2.75}, {4.5, -2.75}, {4.5, 2.75}, {-4.5, 2.75},
														 {-4.5, -2.75}};
	std::vector<CPose2D> path;
	for (std::size_t c = 0; c + 1 < corners.size(); ++c)
	{
		const auto [x0, y0] = corners[c];
		const auto [x1, y1] = corners[c + 1];
		const double length = std::hypot(x1 - x0, y1 - y0), phi = std::atan2(y1 - y0, x1 - x0);
		const int steps = static_cast<int>(std::lround(length / 0.5));
		for (int i = 0; i < steps; ++i)
			path.emplace_back(x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps, phi);
	}
	path.emplace_back(corners.back().first, corners.back().second, -M_PI / 2);
	return path;
}

// The path as wheels that turn 0.25 deg per metre too far would give it, from
// the same start: 0.66 m and 7.3 deg off at the end.
std::vector<CPose2D> drifted(const std::vector<CPose2D>& truth)
{
	std::vector<CPose2D> out{truth[0]};
	for (std::size_t i = 1; i < truth.size(); ++i)
	{
		const CPose2D u = truth[i] - truth[i - 1];
		const double d = std::hypot(u.x(), u.y());
		out.push_back(out.back() + CPose2D(u.x(), u.y(), u.phi() + 0.25 * M_PI / 180 * d));
	}
	return out;
}

double error(const CPose2D& a, const CPose2D& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

double worstError(const std::vector<CPose2D>& a, const std::vector<CPose2D>& b)
{
	double worst = 0;
	for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, error(a[i], b[i]));
	return worst;
}

LoopClosureOptions shipped() { return GuardedIcpOptions::fromIniFile(OMNIRANGE_SOURCE_DIR "/ini/icp-slam-omniscan.ini").loops; }

struct RingDrive
{
	std::vector<CPose2D> truth, estimate;
	int loops{0};
};

// Feeds the drifted keyframes, with scans drawn at the true poses, to a graph.
RingDrive runRing(const LoopClosureOptions& o)
{
	const GuardedIcpOptions matcher = GuardedIcpOptions::fromIniFile(OMNIRANGE_SOURCE_DIR "/ini/icp-slam-omniscan.ini");
	RingDrive r;
	r.truth = ringPath();
	const std::vector<CPose2D> odometry = drifted(r.truth);
	KeyframeGraph graph(o, matcher.icp, matcher.weak_direction_ratio);
	for (std::size_t i = 0; i < r.truth.size(); ++i)
	{
		// As the matcher does: the wheels' motion from where the graph now
		// puts the last keyframe (a closed loop moves it).
		const CPose2D pose = i == 0 ? odometry[0] : graph.pose(i - 1) + (odometry[i] - odometry[i - 1]);
		graph.add(drawScan(kRing, r.truth[i], 1000.0 + i), pose, 0.5 * static_cast<double>(i));
	}
	for (std::size_t i = 0; i < graph.size(); ++i) r.estimate.push_back(graph.pose(i));
	r.loops = graph.loops();
	return r;
}
}  // namespace

TEST(KeyframeGraph, ClosingTheLoopBringsTheRouteBackToTheTruth)
{
	LoopClosureOptions off = shipped();
	off.enabled = false;
	const RingDrive open = runRing(off);
	ASSERT_EQ(open.loops, 0);
	const double drift = error(open.estimate.back(), open.truth.back());
	ASSERT_GT(drift, 0.25);  // the drive's own drift: what there is to correct
	ASSERT_LT(drift, 1.0);  // within the shipped search radius

	const RingDrive closed = runRing(shipped());
	EXPECT_GE(closed.loops, 1);
	EXPECT_LT(error(closed.estimate.back(), closed.truth.back()), 0.05);
	// The correction is spread over the route, not only put on its end: the
	// worst keyframe anywhere comes nearer the truth too.
	EXPECT_LT(worstError(closed.estimate, closed.truth), 0.5 * worstError(open.estimate, open.truth));
	EXPECT_LT(std::abs(mrpt::math::wrapToPi(closed.estimate.back().phi() - closed.truth.back().phi())), 0.5 * M_PI / 180);
}

TEST(KeyframeGraph, ALoopThatTurnsTheRobotMoreThanTheDriftAllowsIsRefused)
{
	// The drive gathers 7.3 deg of heading drift; a gate of 0.5 deg must refuse
	// the loop match that removes it.
	LoopClosureOptions tight = shipped();
	tight.search_turn_deg = 0.5;
	EXPECT_EQ(runRing(tight).loops, 0);
	LoopClosureOptions near = shipped();
	near.search_radius = 0.2;  // shorter than the drift: the drifted estimate passes no old keyframe this near
	EXPECT_EQ(runRing(near).loops, 0);
}

TEST(KeyframeGraph, ACorridorClosesNoLoop)
{
	// Down a straight corridor and back: the scans cannot tell where along it
	// the robot is, so however good the match looks, it closes no loop.
	const GuardedIcpOptions matcher = GuardedIcpOptions::fromIniFile(OMNIRANGE_SOURCE_DIR "/ini/icp-slam-omniscan.ini");
	KeyframeGraph graph(shipped(), matcher.icp, matcher.weak_direction_ratio);
	double driven = 0;
	for (int i = 0; i <= 24; ++i)  // 6 m out, 6 m back
	{
		const double x = i <= 12 ? 0.5 * i : 0.5 * (24 - i);
		graph.add(drawScan(kCorridor, CPose2D(x, 0, i <= 12 ? 0 : M_PI), 1000.0 + i), CPose2D(x * 1.05, 0, i <= 12 ? 0 : M_PI),
				  driven);
		driven += 0.5;
	}
	EXPECT_EQ(graph.loops(), 0);
}

TEST(KeyframeGraph, TheIniSectionIsReadAndCheckedKeyByKey)
{
	const LoopClosureOptions o =
		LoopClosureOptions::fromIni(mrpt::config::CConfigFileMemory("[loop_closure]\nenabled = false\nsearch_radius = 2\n"));
	EXPECT_FALSE(o.enabled);
	EXPECT_DOUBLE_EQ(o.search_radius, 2);
	EXPECT_DOUBLE_EQ(o.min_travel, LoopClosureOptions{}.min_travel);  // absent: the default
	for (const std::string bad : {"loop_sigma = 0", "search_radius = -1", "min_goodness = 1.5", "local_keyframes = -2",
							 "search_radious = 2", "min_travel = 5m"})
	{
		try
		{
			LoopClosureOptions::fromIni(mrpt::config::CConfigFileMemory("[loop_closure]\n" + bad + "\n"));
			ADD_FAILURE() << bad << " was accepted";
		}
		catch (const std::runtime_error& e)
		{
			EXPECT_NE(std::string(e.what()).find(bad.substr(0, bad.find(' '))), std::string::npos) << e.what();
		}
	}
}
TEST(KeyframeGraph, TheMatchersPathMovesWithItsKeyframes)
{
	// The ring driven as a rawlog (a scan every 0.1 m) through the guarded
	// matcher, with wheels that read 8 % long on the first, 9 m leg: along
	// that corridor the scans cannot see it, so the matcher alone comes back
	// to the start 0.42 m off, and the guard refuses the snap.
	std::vector<CPose2D> truth, odometry;
	const std::vector<CPose2D> corners = ringPath();
	for (std::size_t i = 0; i + 1 < corners.size(); ++i)
		for (int j = 0; j < 5; ++j)
		{
			const CPose2D step = corners[i + 1] - corners[i];
			truth.push_back(corners[i] + CPose2D(step.x() * j / 5, step.y() * j / 5, j == 0 ? 0 : step.phi()));
			if (odometry.empty()) odometry.push_back(truth[0]);
			else
			{
				const CPose2D u = truth.back() - truth[truth.size() - 2];
				const double slip = truth.size() <= 90 ? 1.08 : 1.0;  // the first leg: 18 steps of 5 scans
				odometry.push_back(odometry.back() + CPose2D(u.x() * slip, u.y() * slip, u.phi()));
			}
		}
	const Drive d("keyframe_graph_ring.rawlog", static_cast<int>(truth.size()), [&](int i) { return odometry[i]; },
				  [&](int i, double t) { return drawScan(kRing, truth[i], t); });
	GuardedIcpOptions o = GuardedIcpOptions::fromIniFile(OMNIRANGE_SOURCE_DIR "/ini/icp-slam-omniscan.ini");
	const GuardedIcpResult closed = runGuardedIcp(d.file, "OMNISCAN", kOdometryLabel, o);
	o.loops.enabled = false;
	const GuardedIcpResult open = runGuardedIcp(d.file, "OMNISCAN", kOdometryLabel, o);
	ASSERT_EQ(closed.path.size(), truth.size());
	ASSERT_GT(error(truth[0] + open.path.back().pose, truth.back()), 0.3);  // what there is to close
	EXPECT_GE(closed.loops, 1);
	EXPECT_LT(error(truth[0] + closed.path.back().pose, truth.back()), 0.05);
	// Every scan sits where its keyframe now is, plus the short way it truly
	// drove from it (give or take the wheels' 8 % of at most 0.5 m and a
	// centimetre of matching): the scans matched before the loop closed moved
	// with it.
	const auto keyframes = simplemapKeyframes(closed.keyframes);
	ASSERT_GT(keyframes.size(), 20u);
	std::size_t k = 0, truth_k = 0;
	for (std::size_t i = 0; i < truth.size(); ++i)
	{
		while (k + 1 < keyframes.size() && keyframes[k + 1].t <= closed.path[i].t) ++k;
		if (std::abs(keyframes[k].t - closed.path[i].t) < 1e-6) truth_k = i;
		const CPose2D expected = keyframes[k].pose + (truth[i] - truth[truth_k]);
		EXPECT_LT(error(closed.path[i].pose, expected), 0.06) << "scan " << i;
	}
}
