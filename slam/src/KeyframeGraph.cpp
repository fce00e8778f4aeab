#include "omnirange_slam/KeyframeGraph.h"

#include "omnirange_slam/GuardedIcp.h"

#include <mrpt/graphslam/levmarq.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/poses/CPosePDFGaussianInf.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>
#include <utility>
#include <stdexcept>

namespace omnirange::slam
{
namespace
{
constexpr double kDeg = M_PI / 180;

mrpt::poses::CPosePDFGaussianInf edge(const mrpt::poses::CPose2D& relative, double sigma, double sigma_rad)
{
	mrpt::math::CMatrixDouble33 information;
	information.setZero();
	information(0, 0) = information(1, 1) = 1 / (sigma * sigma);
	information(2, 2) = 1 / (sigma_rad * sigma_rad);
	return {relative, information};
}

/** Whether the scan fixes both directions of translation (GuardedIcp.h). */
bool constrainsTranslation(const mrpt::obs::CObservation2DRangeScan& scan, double weak_ratio)
{
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(translationInformation(scan));
	const double weaker = es.eigenvalues()[0], stronger = es.eigenvalues()[1];  // ascending
	return stronger > 0 && weaker >= weak_ratio * stronger;
}
}  // namespace

const OptionsTable<LoopClosureOptions>& LoopClosureOptions::table()
{
	using O = LoopClosureOptions;
	static const auto t =
		OptionsTable<O>()
			.add("enabled", "-", "close loops; false keeps the keyframes where the matcher put them",
				 [](O& o) -> auto& { return o.enabled; })
			.add("min_travel", "m", "odometry driven since an old keyframe before it counts as a loop",
				 [](O& o) -> auto& { return o.min_travel; })
			.within(Range::atLeast(0))
			.add("search_radius", "m", "old keyframes this near the new one are searched",
				 [](O& o) -> auto& { return o.search_radius; })
			.within(Range::atLeast(0))
			.add("search_turn_deg", "deg", "a loop match turning the robot more is refused",
				 [](O& o) -> auto& { return o.search_turn_deg; })
			.within(Range::atLeast(0))
			.add("min_goodness", "-", "ICP goodness a loop match needs", [](O& o) -> auto& { return o.min_goodness; })
			.within(Range::closed(0, 1))
			.add("local_keyframes", "-", "old keyframes either side of the nearest in the map matched against",
				 [](O& o) -> auto& { return o.local_keyframes; })
			.within(Range::atLeast(0))
			.add("chain_sigma", "m", "consecutive keyframes' sigma, its floor", [](O& o) -> auto& { return o.chain_sigma; })
			.within(Range::above(0))
			.add("chain_sigma_per_metre", "m/m", "and its share of the distance driven",
				 [](O& o) -> auto& { return o.chain_sigma_per_metre; })
			.within(Range::atLeast(0))
			.add("chain_sigma_deg", "deg", "their heading's sigma, its floor",
				 [](O& o) -> auto& { return o.chain_sigma_deg; })
			.within(Range::above(0))
			.add("chain_sigma_deg_per_metre", "deg/m", "and its growth with the distance driven",
				 [](O& o) -> auto& { return o.chain_sigma_deg_per_metre; })
			.within(Range::atLeast(0))
			.add("loop_sigma", "m", "a loop match's sigma", [](O& o) -> auto& { return o.loop_sigma; })
			.within(Range::above(0))
			.add("loop_sigma_deg", "deg", "a loop match's heading sigma", [](O& o) -> auto& { return o.loop_sigma_deg; })
			.within(Range::above(0));
	return t;
}

void LoopClosureOptions::validate() const
{
	try
	{
		table().requireRanges(*this);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::invalid_argument("[loop_closure] " + std::string(e.what()));
	}
}

LoopClosureOptions LoopClosureOptions::fromIni(const mrpt::config::CConfigFileBase& ini)
{
	LoopClosureOptions o;
	try
	{
		if (ini.sectionExists("loop_closure")) table().load(o, ini, "loop_closure");  // optional
		o.validate();
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(e.what());
	}
	return o;
}

KeyframeGraph::KeyframeGraph(const LoopClosureOptions& o, const mrpt::slam::CICP::TConfigParams& icp,
							 double weak_ratio)
	: o_(o), weak_ratio_(weak_ratio)
{
	icp_.options = icp;
	graph_.root = 0;
}

bool KeyframeGraph::add(const mrpt::obs::CObservation2DRangeScan::Ptr& scan, const mrpt::poses::CPose2D& pose,
						double driven)
{
	const std::size_t k = keyframes_.size();
	keyframes_.push_back({scan, driven});
	graph_.nodes[k] = pose;
	if (k == 0) return false;
	const mrpt::poses::CPose2D& previous = graph_.nodes.at(k - 1);
	const double d = driven - keyframes_[k - 1].driven;
	graph_.insertEdge(k - 1, k,
					  edge(pose - previous, o_.chain_sigma + o_.chain_sigma_per_metre * d,
						   (o_.chain_sigma_deg + o_.chain_sigma_deg_per_metre * d) * kDeg));
	return o_.enabled && closeLoop(k);
}

bool KeyframeGraph::closeLoop(std::size_t k)
{
	const mrpt::poses::CPose2D& now = graph_.nodes.at(k);
	const auto old = [&](std::size_t i) { return keyframes_[k].driven - keyframes_[i].driven >= o_.min_travel; };
	// The nearest old keyframe within reach.
	std::size_t nearest = k;
	double best = std::numeric_limits<double>::infinity();
	for (std::size_t i = 0; i < k && old(i); ++i)
	{
		const double d = now.distanceTo(graph_.nodes.at(i));
		if (d <= o_.search_radius && d < best) best = d, nearest = i;
	}
	if (nearest == k || !constrainsTranslation(*keyframes_[k].scan, weak_ratio_)) return false;

	mrpt::maps::CSimplePointsMap local, points;
	local.insertionOptions.isPlanarMap = points.insertionOptions.isPlanarMap = true;
	const std::size_t from = nearest >= std::size_t(o_.local_keyframes) ? nearest - o_.local_keyframes : 0;
	for (std::size_t i = from; i <= nearest + o_.local_keyframes && i < k && old(i); ++i)
		local.insertObservation(*keyframes_[i].scan, mrpt::poses::CPose3D(graph_.nodes.at(i)));
	points.insertObservation(*keyframes_[k].scan);
	mrpt::slam::CICP::TReturnInfo info;
	const auto pdf = icp_.Align(&local, &points, now, info);
	// A match still moving when ICP ran out of iterations is sliding along a
	// corridor-like stretch of the old map, not settled on it.
	if (!pdf || info.goodness < o_.min_goodness || info.nIterations >= icp_.options.maxIterations) return false;
	const mrpt::poses::CPose2D matched = pdf->getMeanVal();
	if (matched.distanceTo(now) > o_.search_radius ||
		std::abs(mrpt::math::wrapToPi(matched.phi() - now.phi())) > o_.search_turn_deg * kDeg)
		return false;

	graph_.insertEdge(nearest, k, edge(matched - graph_.nodes.at(nearest), o_.loop_sigma, o_.loop_sigma_deg * kDeg));
	++loops_;
	mrpt::graphslam::TResultInfoSpaLevMarq result;
	mrpt::graphslam::optimize_graph_spa_levmarq(graph_, result);
	return true;
}

mrpt::maps::CSimpleMap KeyframeGraph::simplemap() const
{
	mrpt::maps::CSimpleMap sm;
	for (std::size_t k = 0; k < keyframes_.size(); ++k)
	{
		auto sf = mrpt::obs::CSensoryFrame::Create();
		sf->insert(keyframes_[k].scan);
		auto pdf = mrpt::poses::CPose3DPDFGaussian::Create();
		pdf->mean = mrpt::poses::CPose3D(graph_.nodes.at(k));
		sm.insert(pdf, sf);
	}
	return sm;
}

void KeyframeGraph::insertInto(mrpt::maps::CSimplePointsMap& map) const
{
	for (std::size_t k = 0; k < keyframes_.size(); ++k)
		map.insertObservation(*keyframes_[k].scan, mrpt::poses::CPose3D(graph_.nodes.at(k)));
}

}  // namespace omnirange::slam
