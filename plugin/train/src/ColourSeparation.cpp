#include "omnirange/train/ColourSeparation.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace omnirange
{
ColourSeparation colourSeparation(const ColourModel& model, const FreeSpaceClassifier& classifier, double smoothing)
{
	ColourSeparation s;
	if (!model.hasObstacles() || model.floor.empty()) return s;
	s.known = true;
	const std::vector<double> score = model.floor.smoothedProbabilities(smoothing);
	std::vector<std::uint32_t> bins(score.size());
	std::iota(bins.begin(), bins.end(), 0u);
	std::sort(bins.begin(), bins.end(), [&](std::uint32_t a, std::uint32_t b) { return score[a] < score[b]; });
	// The Mann-Whitney form of the AUC over the two histograms' masses, bins of one score taken together (ties: half).
	double feet_below = 0, auc = 0;
	for (std::size_t i = 0; i < bins.size();)
	{
		std::size_t j = i;
		double floor_here = 0, feet_here = 0;
		for (; j < bins.size() && score[bins[j]] == score[bins[i]]; ++j)
			floor_here += model.floor.probability(bins[j]), feet_here += model.obstacles.probability(bins[j]);
		auc += floor_here * (feet_below + 0.5 * feet_here);
		feet_below += feet_here;
		i = j;
	}
	s.auc = auc;
	for (std::uint32_t b = 0; b < score.size(); ++b)
		if (classifier.isFreeBin(b)) s.feet_read_free += model.obstacles.probability(b);
	return s;
}

std::string separationLine(const ColourSeparation& s)
{
	if (!s.known) return "training saw no obstacle's feet: how well colour parts the floor from obstacles is unknown";
	char line[300];
	const char* how = s.auc >= kWellSeparated ? "well" : s.auc >= kPoorlySeparated ? "only in part" : "poorly";
	const char* expect = s.auc >= kWellSeparated ? "expect few unsure rays"
						 : s.auc >= kPoorlySeparated ? "expect unsure rays where obstacles look like the floor"
													 : "expect many unsure rays";
	std::snprintf(line, sizeof line,
				  "colour separates floor from obstacles %s here (AUC %.2f; %.0f %% of the obstacles' feet read as "
				  "floor): %s",
				  how, s.auc, 100 * s.feet_read_free, expect);
	return line;
}

}  // namespace omnirange
