#include "omnirange_slam/GuardedIcp.h"
#include "omnirange_slam/IcpSlamIni.h"

#include <omnirange/core/Rangefinder.h>
#include <omnirange/io/RawlogProcessor.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/poses/CPosePDFGaussian.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <utility>

namespace omnirange::slam
{
namespace
{
constexpr double kDeg = M_PI / 180;

double positiveKey(const mrpt::config::CConfigFileBase& ini, const std::string& section, const std::string& key,
				   double fallback)
{
	if (!ini.keyExists(section, key)) return fallback;
	const std::string text = readRawValue(ini, section, key);
	double v = 0;
	try
	{
		v = parseDouble(text);  // strictly: MRPT's reader takes "0.2m" as 0.2 and "0,4" as 0
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error("[" + section + "] " + key + " = '" + text + "': " + e.what());
	}
	if (v < 0) throw std::runtime_error("[" + section + "] " + key + " must be a number >= 0, not " + text);
	return v;
}

/** Whether `d` moves farther than `lin` metres or turns more than `ang_deg`:
 * icp-slam's rule for when to match and when to insert a keyframe. */
bool beyond(const mrpt::poses::CPose2D& d, double lin, double ang_deg)
{
	return std::hypot(d.x(), d.y()) >= lin || std::abs(d.phi()) >= ang_deg * kDeg;
}

/** Odometric motion, which bounds how far the wheels can have erred. */
}  // namespace

const OptionsTable<GuardedIcpOptions>& GuardedIcpOptions::guardTable()
{
	using O = GuardedIcpOptions;
	static const auto t =
		OptionsTable<O>()
			.add("max_jump", "m", "a match may move the robot this far from the odometry's prediction",
				 [](O& o) -> auto& { return o.max_jump; })
			.within(Range::atLeast(0))
			.add("max_jump_per_metre", "m/m", "plus this much per metre driven since the last match",
				 [](O& o) -> auto& { return o.max_jump_per_metre; })
			.within(Range::atLeast(0))
			.add("max_turn_deg", "deg", "and turn it this far", [](O& o) -> auto& { return o.max_turn_deg; })
			.within(Range::atLeast(0))
			.add("max_turn_per_radian", "deg/deg", "plus this much per angle turned since the last match",
				 [](O& o) -> auto& { return o.max_turn_per_radian; })
			.within(Range::atLeast(0))
			.add("weak_direction_ratio", "-",
				 "a direction with less than this share of the strongest's information is left to the odometry",
				 [](O& o) -> auto& { return o.weak_direction_ratio; })
			.within(Range::closed(0, 1));
	return t;
}

GuardedIcpOptions GuardedIcpOptions::fromIni(const mrpt::config::CConfigFileBase& ini)
{
	GuardedIcpOptions o;
	o.icp.loadFromConfigFile(ini, "ICP");
	// icp-slam's own sections, read as it reads them (MRPT's keys beside ours).
	const std::string app = "MappingApplication", points = "MappingApplication_pointsMap_00_insertOpts";
	const struct
	{
		const std::string& section;
		const char* key;
		double& value;
	} keys[] = {{app, "localizationLinDistance", o.localization_lin},
				{app, "localizationAngDistance", o.localization_ang_deg},
				{app, "insertionLinDistance", o.insertion_lin},
				{app, "insertionAngDistance", o.insertion_ang_deg},
				{app, "minICPgoodnessToAccept", o.min_goodness},
				{points, "minDistBetweenLaserPoints", o.min_dist_between_points}};
	for (const auto& k : keys) k.value = positiveKey(ini, k.section, k.key, k.value);
	try
	{
		if (ini.sectionExists("odometry_guard")) guardTable().load(o, ini, "odometry_guard");  // optional, ranges checked
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(e.what());
	}
	o.loops = LoopClosureOptions::fromIni(ini);
	return o;
}

GuardedIcpOptions GuardedIcpOptions::fromIniFile(const std::string& file)
{
	if (!std::filesystem::is_regular_file(file)) throw std::runtime_error("cannot read ini '" + file + "'");
	requireStrictIcpSection(file);
	try
	{
		return fromIni(mrpt::config::CConfigFile(file));
	}
	catch (const std::exception& e)  // ours or MRPT's: name the file the key is in
	{
		const std::string what = e.what();
		throw std::runtime_error(what.rfind(file, 0) == 0 ? what : file + ": " + what);
	}
}

Eigen::Matrix2d translationInformation(const mrpt::obs::CObservation2DRangeScan& scan)
{
	const int n = static_cast<int>(scan.getScanSize());
	Eigen::Matrix2d H = Eigen::Matrix2d::Zero();
	if (n < 5) return H;
	// A full circle's first and last rays are neighbours; a laser's are not.
	const bool circle = scan.aperture > 2 * M_PI * (1 - 1.5 / n);
	std::vector<Eigen::Vector2d> p(n);
	for (int i = 0; i < n; ++i)
	{
		const double a = scan.sensorPose.yaw() + scan.getScanAngle(i);
		p[i] = scan.getScanRange(i) * Eigen::Vector2d(std::cos(a), std::sin(a));
	}
	constexpr int kSide = 2;  // rays either side that give the wall's direction
	constexpr double kNear = 0.2;  // [m] farther apart, the neighbours are another object
	const auto valid = [&](int i) { return (circle || (i >= 0 && i < n)) && scan.getScanRangeValidity((i + n) % n); };
	for (int i = 0; i < n; ++i)
	{
		if (!valid(i) || !valid(i - kSide) || !valid(i + kSide)) continue;
		const Eigen::Vector2d& a = p[(i - kSide + n) % n];
		const Eigen::Vector2d& b = p[(i + kSide) % n];
		if ((a - p[i]).norm() > kNear || (b - p[i]).norm() > kNear) continue;
		const Eigen::Vector2d d = b - a;
		if (d.norm() < 1e-9) continue;
		const Eigen::Vector2d normal(-d.y() / d.norm(), d.x() / d.norm());
		H += normal * normal.transpose();
	}
	return H;
}

mrpt::math::TPose2D keepConstrainedCorrection(const mrpt::math::TPose2D& predicted, const mrpt::math::TPose2D& matched,
											  const Eigen::Matrix2d& information, double weak_ratio, int& weak)
{
	const double c = std::cos(matched.phi), s = std::sin(matched.phi);
	Eigen::Matrix2d R;
	R << c, -s, s, c;
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(R * information * R.transpose());
	const Eigen::Vector2d correction(matched.x - predicted.x, matched.y - predicted.y);
	const double strongest = es.eigenvalues()[1];  // ascending
	Eigen::Vector2d kept = Eigen::Vector2d::Zero();
	for (int k = 0; k < 2; ++k)
	{
		const Eigen::Vector2d v = es.eigenvectors().col(k);
		if (strongest > 0 && es.eigenvalues()[k] >= weak_ratio * strongest)
			kept += v * v.dot(correction);
		else
			++weak;
	}
	return {predicted.x + kept.x(), predicted.y + kept.y(), matched.phi};
}

GuardedMatcher::GuardedMatcher(const GuardedIcpOptions& o)
	: o_(o), graph_(o.loops, o.icp, o.weak_direction_ratio)
{
	map_.insertionOptions.minDistBetweenLaserPoints = static_cast<float>(o.min_dist_between_points);
	map_.insertionOptions.fuseWithExisting = false;
	map_.insertionOptions.isPlanarMap = true;
	icp_.options = o.icp;
}

void GuardedMatcher::onOdometry(const mrpt::poses::CPose2D& u)
{
	++odometry_seen_;
	pose_ = pose_ + u;
	since_.lin += std::hypot(u.x(), u.y());
	since_.ang += std::abs(u.phi());
	driven_ += std::hypot(u.x(), u.y());
}

void GuardedMatcher::insertKeyframe(const mrpt::obs::CObservation2DRangeScan::Ptr& scan)
{
	const mrpt::poses::CPose2D before = pose_;
	if (!graph_.add(scan, pose_, driven_))
	{
		map_.insertObservation(*scan, mrpt::poses::CPose3D(pose_));
		return;
	}
	// A loop closed: every keyframe moved. The matcher goes on from the
	// newest keyframe's new pose, against a map rebuilt from them all.
	pose_ = graph_.pose(graph_.size() - 1);
	last_match_ = pose_ + (last_match_ - before);
	map_.clear();
	graph_.insertInto(map_);
}

void GuardedMatcher::match(const mrpt::obs::CObservation2DRangeScan& scan)
{
	last_match_ = pose_;
	mrpt::maps::CSimplePointsMap points;
	points.insertionOptions.isPlanarMap = true;
	points.insertObservation(scan);
	mrpt::slam::CICP::TReturnInfo info;
	const auto pdf = icp_.Align(&map_, &points, pose_, info);
	if (!pdf || info.goodness < o_.min_goodness)
	{
		++counts_.poor_matches;
		return;
	}
	const mrpt::poses::CPose2D matched = pdf->getMeanVal();
	const mrpt::poses::CPose2D jump = matched - pose_;
	const bool too_far = std::hypot(jump.x(), jump.y()) > o_.max_jump + o_.max_jump_per_metre * since_.lin ||
						 std::abs(jump.phi()) > o_.max_turn_deg * kDeg + o_.max_turn_per_radian * since_.ang;
	if (too_far)
	{
		++counts_.refused_jumps;
		return;
	}
	pose_ = mrpt::poses::CPose2D(keepConstrainedCorrection(pose_.asTPose(), matched.asTPose(),
														   translationInformation(scan), o_.weak_direction_ratio,
														   counts_.weak_directions));
	++counts_.matches;
	since_ = {};
}

void GuardedMatcher::onScan(const mrpt::obs::CObservation2DRangeScan::Ptr& scan)
{
	const double t = mrpt::Clock::toDouble(scan->timestamp);
	if (map_.empty())  // until a scan has put points in the map, there is nothing to match
	{
		insertKeyframe(scan);
		last_match_ = pose_;
		scans_.push_back({t, graph_.size() - 1, mrpt::poses::CPose2D()});
		return;
	}
	if (beyond(pose_ - last_match_, o_.localization_lin, o_.localization_ang_deg)) match(*scan);
	const auto keyframe = [&] { return graph_.pose(graph_.size() - 1); };
	if (beyond(pose_ - keyframe(), o_.insertion_lin, o_.insertion_ang_deg)) insertKeyframe(scan);
	scans_.push_back({t, graph_.size() - 1, pose_ - keyframe()});
}

GuardedIcpResult GuardedMatcher::result() const
{
	GuardedIcpResult r = counts_;
	for (const Anchored& a : scans_) r.path.push_back({a.t, graph_.pose(a.keyframe) + a.relative});
	r.keyframes = graph_.simplemap();
	r.loops = graph_.loops();
	return r;
}

GuardedIcpResult runGuardedIcp(const std::string& rawlog, const std::string& scan_label,
							   const std::string& odometry_label, const GuardedIcpOptions& o)
{
	using mrpt::obs::CObservation2DRangeScan;
	using mrpt::obs::CObservationOdometry;
	GuardedMatcher matcher(o);
	mrpt::poses::CPose2D last_odometry;
	bool have_odometry = false;
	RawlogProcessor loop(rawlog);
	loop.on<CObservationOdometry>(odometry_label, [&](const CObservationOdometry::Ptr& odo) {
		matcher.onOdometry(have_odometry ? odo->odometry - last_odometry : mrpt::poses::CPose2D());
		last_odometry = odo->odometry;
		have_odometry = true;
	});
	// The actions/sensory-frames format (older datasets, rawlog-grabber with
	// use_sensoryframes = 1) carries the odometry as each frame's increment.
	loop.onObject([&](const mrpt::serialization::CSerializable::Ptr& object) {
		if (const auto actions = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(object))
			if (const auto move = actions->getBestMovementEstimation()) matcher.onOdometry(move->rawOdometryIncrementReading);
	});
	loop.on<CObservation2DRangeScan>(scan_label, [&](const CObservation2DRangeScan::Ptr& scan) {
		// An unsure ray (written as an obstacle for a navigator) is neither a wall to match nor free floor to
		// clear. Only the omnicam's and the fused scans carry confidence: a laser's intensity is its return's strength.
		if (scan->sensorLabel == kOmniscanLabel || scan->sensorLabel == kFusedLabel) invalidateUnsureRays(*scan);
		matcher.onScan(scan);
	});
	loop.run();
	if (matcher.scansSeen() == 0)
		throw std::runtime_error("no " + scan_label + " scan in '" + rawlog + "' (" + loop.describeLabels() + ")");
	if (matcher.odometrySeen() == 0)
		throw std::runtime_error("no " + odometry_label + " odometry in '" + rawlog + "' (" + loop.describeLabels() +
								 ", and no robot-movement action): the guard needs the wheels");
	return matcher.result();
}

}  // namespace omnirange::slam
