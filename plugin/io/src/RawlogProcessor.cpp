#include "omnirange/io/RawlogProcessor.h"

#include "omnirange/io/Progress.h"

#include <mrpt/obs/CSensoryFrame.h>

namespace omnirange
{
RawlogProcessor::RawlogProcessor(const std::string& path) : reader_(path) {}

void RawlogProcessor::run(Progress* progress)
{
	stopped_ = false;
	const auto visit = [&](const mrpt::obs::CObservation::Ptr& obs) {
		labels_.insert(obs->sensorLabel);
		for (const auto& hook : observation_hooks_)
			if (!stopped_) hook(obs);
	};
	while (!stopped_)
	{
		const auto obj = reader_.next();
		if (!obj) break;
		for (const auto& hook : object_hooks_) hook(obj);
		if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj))
			visit(obs);
		else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
			for (const auto& o : *sf) visit(o);
		// Action collections (the other format's odometry) reach only onObject().
		if (progress) progress->update(reader_.objectsRead());
	}
	reader_.requireImagesUnchanged();  // also when a hook stopped it before the end
	if (progress) progress->finish();
}

std::string RawlogProcessor::describeLabels() const
{
	if (labels_.empty()) return "no observation at all";
	std::string all;
	for (const auto& l : labels_) all += (all.empty() ? "" : ", ") + l;
	return "the labels found: " + all;
}

std::string RawlogProcessor::describeNoPair() const
{
	std::string why;
	for (const auto& f : no_pair_) why += (why.empty() ? "" : "; ") + f();
	return why + " in '" + path() + "' (" + describeLabels() + ")";
}

}  // namespace omnirange
