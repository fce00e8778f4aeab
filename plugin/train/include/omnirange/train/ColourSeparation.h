#pragma once
// How well a trained colour model tells the floor from what stands on it,
// measured on its own training data: the floor's pixels the laser showed
// free against the obstacles' feet just beyond its returns. Where the two
// share their colours, no threshold can part them and the scan will be
// unsure there (docs/users.md, "When the room is blind").

#include <omnirange/core/ColourModel.h>
#include <omnirange/core/FreeSpaceClassifier.h>

#include <string>

namespace omnirange
{
struct ColourSeparation
{
	bool known{false};  ///< false: training saw no obstacle's feet
	/** [-] the chance that a floor pixel's colour is likelier floor (the
	 * model's P(colour | floor)) than an obstacle foot's: 1 parts them
	 * fully, 0.5 not at all. */
	double auc{0.5};
	double feet_read_free{0};  ///< [-] share of the obstacles' feet the classifier calls free floor
};

/** The separation of `model` under the colour probabilities a classifier
 * with `smoothing` uses, and the share of obstacle feet `classifier` reads free. */
ColourSeparation colourSeparation(const ColourModel& model, const FreeSpaceClassifier& classifier, double smoothing);

/** [-] AUCs from which colour parts the floor from its obstacles well, and
 * below which poorly (between: in part). */
inline constexpr double kWellSeparated = 0.9, kPoorlySeparated = 0.75;

/** One sentence for a user: what to expect of the scan in this room. */
std::string separationLine(const ColourSeparation& s);

}  // namespace omnirange
