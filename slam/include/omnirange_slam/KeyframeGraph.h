#pragma once
// Loop closure for the guarded matcher (GuardedIcp.h): its keyframes are the
// nodes of a pose graph. Consecutive keyframes are joined by the matcher's
// relative pose, trusted less the farther the robot drove between them. When a
// new keyframe lies near one made long before, its scan is matched against the
// old keyframes there; a good match adds a loop edge and MRPT's sparse pose
// adjustment spreads the loop's error back over the route, rotation included
// (the correction the paper names and never built).
// docs/method.md ("Closing loops") has the why and the limits.

#include <omnirange/config/OptionsTable.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/slam/CICP.h>

#include <string>
#include <vector>

namespace omnirange::slam
{
struct LoopClosureOptions
{
	/** [loop_closure] section of the icp-slam ini. false: keyframes are kept
	 * where the matcher put them, as icp-slam does. */
	bool enabled{true};
	/** [m] odometry driven since an old keyframe before a match against it
	 * counts as a loop (closer in time, the matcher already saw it). */
	double min_travel{5};
	/** [m] old keyframes within this distance of the new keyframe's estimate
	 * are searched: the drift a loop may have gathered. */
	double search_radius{1};
	/** [deg] the heading drift a loop may have gathered: a loop match turning
	 * the robot more is refused (a square room matches itself turned 90 deg). */
	double search_turn_deg{10};
	/** ICP goodness a loop match needs; above the matcher's, since a wrong loop
	 * bends the whole route. */
	double min_goodness{0.6};
	/** Old keyframes either side of the nearest that make the map matched against. */
	int local_keyframes{2};
	/** Standard deviation of consecutive keyframes' relative pose: a floor plus
	 * a share of the distance driven between them [m, m/m, deg, deg/m]. */
	double chain_sigma{0.01}, chain_sigma_per_metre{0.05};
	double chain_sigma_deg{0.2}, chain_sigma_deg_per_metre{0.5};
	/** Standard deviation of a loop match's relative pose [m, deg]. */
	double loop_sigma{0.03}, loop_sigma_deg{0.5};

	/** Reads the [loop_closure] section strictly (an unknown or unparsable key
	 * is an error naming it) and validates it; throws std::runtime_error. */
	static LoopClosureOptions fromIni(const mrpt::config::CConfigFileBase& ini);
	static const OptionsTable<LoopClosureOptions>& table();
	void validate() const;  ///< throws std::invalid_argument naming the key
};

class KeyframeGraph
{
public:
	/** `weak_ratio`: a scan whose weaker translation direction holds less than
	 * this share of the stronger's information (GuardedIcp.h) closes no loop. */
	KeyframeGraph(const LoopClosureOptions& o, const mrpt::slam::CICP::TConfigParams& icp, double weak_ratio);

	/** Adds a keyframe at `pose`, `driven` metres of odometry from the start.
	 * With loop closure on, it is matched against old keyframes near it; when
	 * that closes a loop, the graph is optimised. Returns whether poses moved. */
	bool add(const mrpt::obs::CObservation2DRangeScan::Ptr& scan, const mrpt::poses::CPose2D& pose, double driven);

	std::size_t size() const { return keyframes_.size(); }
	const mrpt::poses::CPose2D& pose(std::size_t k) const { return graph_.nodes.at(k); }
	int loops() const { return loops_; }

	/** Every keyframe's scan at its current pose, as icp-slam's _finalmap_.simplemap. */
	mrpt::maps::CSimpleMap simplemap() const;
	/** Inserts every keyframe's scan at its current pose into `map`. */
	void insertInto(mrpt::maps::CSimplePointsMap& map) const;

private:
	struct Keyframe
	{
		mrpt::obs::CObservation2DRangeScan::Ptr scan;
		double driven{0};
	};
	bool closeLoop(std::size_t k);

	LoopClosureOptions o_;
	mrpt::slam::CICP icp_;
	double weak_ratio_;
	std::vector<Keyframe> keyframes_;
	mrpt::graphs::CNetworkOfPoses2DInf graph_;
	int loops_{0};
};

}  // namespace omnirange::slam
