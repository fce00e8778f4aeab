#pragma once
// A scan matcher with odometry, as icp-slam is (each scan matched against a
// points map of earlier keyframes, the odometry as the first guess), with a
// guard that icp-slam lacks: the odometry also judges the match.
// - A match that moves the robot farther from the odometry's prediction than
//   the wheels can err over the distance since the last match is refused
//   (a scan of 3.8 m matched to the wrong wall at a turn).
// - Along a direction the scan cannot fix (a corridor's length, one wall's
//   length: the scan's wall normals leave it unconstrained), the odometry's
//   prediction is kept and the match's correction dropped.
// Its keyframes form a pose graph that closes loops (KeyframeGraph.h).
// docs/method.md ("Maps from the omnicam: the odometry guard") has the why.

#include <omnirange_slam/KeyframeGraph.h>
#include <omnirange_slam/StampedPose.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/slam/CICP.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace omnirange::slam
{
struct GuardedIcpOptions
{
	/** The matcher: [ICP] of an icp-slam ini, read as icp-slam reads it. */
	mrpt::slam::CICP::TConfigParams icp;
	/** [MappingApplication]: match after this much odometric motion; insert a
	 * keyframe after this much estimated motion; accept a match this good. */
	double localization_lin{0.2}, localization_ang_deg{5};
	double insertion_lin{0.5}, insertion_ang_deg{15};
	double min_goodness{0.40};
	/** [MappingApplication_pointsMap_00_insertOpts] minDistBetweenLaserPoints. */
	double min_dist_between_points{0.05};

	/** [odometry_guard] How far a match may move the robot from the odometry's
	 * prediction: max_jump + max_jump_per_metre x the distance driven since the
	 * last accepted match [m]; the same for the heading [deg, deg per rad turned]. */
	double max_jump{0.05}, max_jump_per_metre{0.1};
	double max_turn_deg{3}, max_turn_per_radian{0.1};
	/** A direction of translation whose information (sum of the scan's wall
	 * normals' outer products) is below this share of the strongest one's is
	 * left to the odometry. 0: never. */
	double weak_direction_ratio{0.1};

	/** [loop_closure] The keyframes as a pose graph (KeyframeGraph.h). */
	LoopClosureOptions loops;

	/** Reads an icp-slam ini ([MappingApplication], [ICP], the points map's
	 * insertion options, as icp-slam reads them) and the optional
	 * [odometry_guard] and [loop_closure] sections, which are ours and read
	 * strictly (an unknown or unparsable key is an error naming it). Throws
	 * std::runtime_error. */
	static GuardedIcpOptions fromIni(const mrpt::config::CConfigFileBase& ini);
	/** The [odometry_guard] keys. */
	static const OptionsTable<GuardedIcpOptions>& guardTable();
	static GuardedIcpOptions fromIniFile(const std::string& file);
};

struct GuardedIcpResult
{
	mrpt::maps::CSimpleMap keyframes;  ///< as icp-slam's _finalmap_.simplemap: each keyframe's scan at its pose
	std::vector<StampedPose> path;  ///< the estimated pose at every scan, with the loops closed after it
	int matches{0};  ///< matches accepted
	int poor_matches{0};  ///< below min_goodness: the odometry's prediction kept
	int refused_jumps{0};  ///< refused by the guard
	int weak_directions{0};  ///< directions left to the odometry in accepted matches
	int loops{0};  ///< loops closed
};

/** The matcher itself, fed one observation at a time in the order they
 * were taken: odometry increments and scans. What omnirange-slam and the
 * experiment run over a rawlog (runGuardedIcp), and what a live robot could
 * call as its sensors report. */
class GuardedMatcher
{
   public:
	explicit GuardedMatcher(const GuardedIcpOptions& o);
	/** The wheels moved the robot by `increment` (in its own frame). */
	void onOdometry(const mrpt::poses::CPose2D& increment);
	/** A scan: matched against the map of keyframes where the robot has moved
	 * far enough since the last match, kept only if the odometry allows it,
	 * and made a keyframe where the robot has moved far enough from the last. */
	void onScan(const mrpt::obs::CObservation2DRangeScan::Ptr& scan);
	/** The current pose estimate. */
	const mrpt::poses::CPose2D& pose() const { return pose_; }
	std::size_t odometrySeen() const { return odometry_seen_; }
	std::size_t scansSeen() const { return scans_.size(); }
	/** The path (every scan's pose, with the loops closed since), the
	 * keyframes and the counters so far. */
	GuardedIcpResult result() const;

   private:
	/** Odometric motion since the last accepted match. */
	struct Motion
	{
		double lin{0}, ang{0};  ///< [m], [rad]
	};
	/** A scan's pose relative to the keyframe before it: closing a loop
	 * later moves it with its keyframe. */
	struct Anchored
	{
		double t;
		std::size_t keyframe;
		mrpt::poses::CPose2D relative;
	};
	void match(const mrpt::obs::CObservation2DRangeScan& scan);
	void insertKeyframe(const mrpt::obs::CObservation2DRangeScan::Ptr& scan);

	GuardedIcpOptions o_;
	mrpt::maps::CSimplePointsMap map_;
	mrpt::slam::CICP icp_;
	KeyframeGraph graph_;
	mrpt::poses::CPose2D pose_, last_match_;
	std::size_t odometry_seen_{0};
	double driven_{0};  ///< [m] odometric distance from the start
	Motion since_;
	std::vector<Anchored> scans_;
	GuardedIcpResult counts_;  ///< the counters; path and keyframes filled by result()
};

/** Runs a GuardedMatcher over a rawlog's scans of one label and its odometry, in
 * file order (streamed). The odometry is the CObservationOdometry readings of
 * `odometry_label`, or, in the actions/sensory-frames format, each frame's
 * robot-movement action. Throws std::runtime_error when it holds no such
 * scans or no odometry. */
GuardedIcpResult runGuardedIcp(const std::string& rawlog, const std::string& scan_label,
							   const std::string& odometry_label, const GuardedIcpOptions& o);

/** The information a scan gives about the robot's translation, in the robot's
 * frame: the sum over its hits of n n^T, n the wall's normal there (from the
 * hits two rays either side, when they lie within 0.2 m). A straight corridor
 * gives a matrix with one small eigenvalue, along the corridor. */
Eigen::Matrix2d translationInformation(const mrpt::obs::CObservation2DRangeScan& scan);

/** The correction from `predicted` to `matched` with its components along the
 * weak directions of `information` (robot frame, rotated by the matched
 * heading) dropped: the pose kept. `weak` counts the directions dropped. */
mrpt::math::TPose2D keepConstrainedCorrection(const mrpt::math::TPose2D& predicted, const mrpt::math::TPose2D& matched,
											  const Eigen::Matrix2d& information, double weak_ratio, int& weak);

}  // namespace omnirange::slam
