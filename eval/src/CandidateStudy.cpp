#include "omnirange_eval/CandidateStudy.h"

#include "omnirange_eval/TruthComparison.h"

#include <omnirange/core/Threads.h>
#include <omnirange/io/ObservationImage.h>
#include <omnirange/io/RawlogProcessor.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>

#include <algorithm>
#include <cstdio>


namespace omnirange::eval
{
namespace
{
using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationImage;

struct Frame
{
	cv::Mat image;
	CObservation2DRangeScan::Ptr truth;
};

std::vector<Frame> framesAfter(const RangefinderParams& start, const CandidateStudyOptions& o, Progress* progress)
{
	std::vector<Frame> frames;
	RawlogProcessor loop(o.rawlog);
	int seen = 0;
	loop.onPair<CObservationImage, CObservation2DRangeScan>(
		o.omni_label, o.truth_label, o.max_dt,
		[&](const CObservationImage::Ptr& image, const CObservation2DRangeScan::Ptr& truth) {
			if (seen++ >= o.first) frames.push_back({decodeImage(*image, start.camera), truth});
		});
	loop.run(progress);
	if (seen == 0) throw std::runtime_error(loop.describeNoPair());
	if (frames.empty())
		throw std::runtime_error("all " + std::to_string(seen) + " image/truth pairs of '" + o.rawlog +
								 "' come before the first one scored (" + std::to_string(o.first) + ")");
	return frames;
}

bool sameCandidate(const LearnedCandidate& a, const LearnedCandidate& b)
{
	return a.space == b.space && a.bins == b.bins && a.threshold == b.threshold &&
		   a.obstacle_ratio == b.obstacle_ratio && a.smoothing == b.smoothing && a.N == b.N && a.K == b.K &&
		   a.boundary == b.boundary && a.step_threshold == b.step_threshold && a.step_sign == b.step_sign;
}

std::string rowOf(const LearnedCandidate& c, bool chosen, const TruthStats& s)
{
	const TruthBand all = s.all();
	const double rays = static_cast<double>(std::max<std::size_t>(1, all.rays));
	const double open = static_cast<double>(std::max<std::size_t>(1, s.open_rays));
	char row[300];
	std::snprintf(row, sizeof row, ",%.6f,%d,%.4f,%.4f,%.5f,%.4f,%.4f,", c.score, chosen ? 1 : 0,
				  all.within_2cm / rays, all.within_5cm / rays, all.meanAbs(), all.missed() / rays,
				  s.false_obstacles / open);
	return candidateColumns(c) + row + spaceSeparated(c.frame_errors) + "," + spaceSeparated(c.frame_shortfalls) + "\n";
}
}  // namespace

std::string studyCandidates(const LearningResult& learned, const RangefinderParams& start,
							const CandidateStudyOptions& o, Progress* progress)
{
	if (start.floor_adaptation)
		throw std::invalid_argument("the candidate study scans without floor adaptation; set floor_adaptation = false");
	const std::vector<Frame> frames = framesAfter(start, o, progress);
	const std::vector<LearnedCandidate>& tried = learned.tried;
	std::vector<std::string> rows(tried.size());
	forEachOnThreads(static_cast<int>(tried.size()), [&](int i) {
		const LearnedCandidate& c = tried[i];
		// The chosen one as it runs: with the edge bias learned for it.
		const bool chosen = sameCandidate(c, learned.best);
		const Rangefinder rf(chosen ? learned.params : withCandidate(start, c), learned.models.at(histogramKeyOf(c)));
		TruthStats s;
		for (const Frame& f : frames) s.add(*f.truth, *rf.toObservation(rf.process(f.image), f.truth->timestamp));
		rows[i] = rowOf(c, chosen, s);
	});
	std::string csv = candidateColumns() +
					  ",score_m,chosen,route_within_2cm,route_within_5cm,route_mean_abs_m,route_missed,"
					  "route_false_obstacles,frame_errors_m,frame_shortfalls_m\n";
	for (const std::string& row : rows) csv += row;
	return csv;
}

}  // namespace omnirange::eval
