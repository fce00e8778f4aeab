#include "omnirange_eval/KeyframeGraph.h"

#include "omnirange_eval/GuardedIcp.h"

#include <mrpt/graphslam/levmarq.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/poses/CPosePDFGaussianInf.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace omnirange::eval
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

LoopClosureOptions LoopClosureOptions::fromIni(const mrpt::config::CConfigFileBase& ini)
{
	const std::string s = "loop_closure";
	LoopClosureOptions o;
	o.enabled = ini.read_bool(s, "enabled", o.enabled);
	const struct
	{
		const char* key;
		double& value;
		bool positive;  ///< > 0, not only >= 0
	} keys[] = {{"min_travel", o.min_travel, false},
				{"search_radius", o.search_radius, false},
				{"search_turn_deg", o.search_turn_deg, false},
				{"min_goodness", o.min_goodness, false},
				{"chain_sigma", o.chain_sigma, true},
				{"chain_sigma_per_metre", o.chain_sigma_per_metre, false},
				{"chain_sigma_deg", o.chain_sigma_deg, true},
				{"chain_sigma_deg_per_metre", o.chain_sigma_deg_per_metre, false},
				{"loop_sigma", o.loop_sigma, true},
				{"loop_sigma_deg", o.loop_sigma_deg, true}};
	for (const auto& k : keys)
	{
		k.value = ini.read_double(s, k.key, k.value);
		if (!std::isfinite(k.value) || k.value < 0 || (k.positive && k.value == 0))
			throw std::runtime_error("[" + s + "] " + k.key + " must be a number " + (k.positive ? "> 0" : ">= 0") +
									 ", not " + std::to_string(k.value));
	}
	o.local_keyframes = ini.read_int(s, "local_keyframes", o.local_keyframes);
	if (o.local_keyframes < 0) throw std::runtime_error("[" + s + "] local_keyframes must be >= 0");
	if (o.min_goodness > 1) throw std::runtime_error("[" + s + "] min_goodness must be in [0, 1]");
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

}  // namespace omnirange::eval
