#pragma once
// How every candidate that learning tried does on the rest of a route,
// scored against the truth: what learning could have had, beside what its
// held-aside frames made it choose. A study for the method's docs, not a
// step of the pipeline: learning itself only ever sees the laser.

#include <omnirange/io/ObservationPairer.h>
#include <omnirange/train/ParameterLearning.h>

#include <string>

namespace omnirange
{
class Progress;
}

namespace omnirange::eval
{
struct CandidateStudyOptions
{
	std::string rawlog;  ///< with the omnicam's images and the simulator's TRUTH
	int first{0};  ///< image/truth pairs before this one are skipped (the training part)
	std::string omni_label{"OMNICAM"}, truth_label{"TRUTH"};
	double max_dt{kDefaultMaxPairingDt};  ///< [s] an image and a truth scan further apart are no pair
};

/** One CSV row per candidate of `learned.tried`, in its order: the
 * candidate's columns, its score on the held-aside frames, whether learning
 * chose it, and on the rest of the route (each with the histogram it would
 * have had, LearningResult::models, and the final options of `start`, the
 * wall fit too; the chosen one with the edge bias learned for it, the others
 * without, as it is learned for the winner only): rays within 2 and 5 cm of the truth, the mean absolute
 * error of the hits, rays missed and false obstacles (TruthComparison.h);
 * last, its error on each held-aside frame and the part of it where the
 * omnicam read nearer than the laser (LearnedCandidate).
 * The scored frames' images are kept in memory (the living room's 195
 * frames of 1024x768: 580 MB peak, against 185 MB without the study). Throws std::runtime_error when the rawlog
 * has no image/truth pair after `first`, std::invalid_argument with
 * floor_adaptation on (the study scans every frame alike). */
std::string studyCandidates(const LearningResult& learned, const RangefinderParams& start,
							const CandidateStudyOptions& o, Progress* progress = nullptr);

}  // namespace omnirange::eval
