#pragma once
// The tuner's pictures, drawn with OpenCV so that they are tested without a
// display: the omnicam image with what the rangefinder saw on it, the scan
// from above beside the laser's, and the floor's colours.

#include <omnirange_tuner/TunerSession.h>

#include <opencv2/core.hpp>

namespace omnirange::tuner
{
struct OverlayOptions
{
	bool classification{true};  ///< free-floor pixels tinted blue in diagonal stripes
	bool scanlines{false};  ///< every scanline_step-th scanline, grey
	bool rays{true};  ///< each ray's end, coloured by its status
	bool candidates{true};  ///< the last candidate each ray's K filter turned down, orange
	bool laser{true};  ///< the laser's hits, cyan
	bool truth{true};  ///< where the floor really ends (TRUTH), white
	bool camera{true};  ///< the set-up checks: base, max-range and horizon circles, forward arrow
	bool legend{true};  ///< a key to the colours shown, in the image's top-left corner
	int scanline_step{8};
};

/** The colours (B, G, R) of the overlays, for the legend and the tests. */
namespace colour
{
// Each colour means one thing: the max-range circle is not no-hit's yellow,
// the forward arrow not too-close's red; free floor is striped, not a solid
// tint an obstacle of that colour could be taken for.
inline const cv::Scalar kHit{0, 255, 0}, kNoHit{0, 255, 255}, kTooClose{0, 0, 255}, kOutlier{255, 0, 255},
	kRejectedCandidate{0, 165, 255}, kLaser{255, 255, 0}, kTruth{255, 255, 255}, kFree{255, 0, 0},
	kForward{255, 255, 255}, kCircle{200, 200, 200}, kMaxRange{160, 160, 160}, kByStep{0, 90, 0},
	kPlaceholder{40, 40, 90}, kLegend{20, 20, 20}, kUnsure{147, 20, 255};
}

/** What is shown instead of a frame that cannot be: `size`, filled with
 * kPlaceholder, with `reason` written on it (wrapped), and no other frame's picture. */
cv::Mat drawPlaceholder(cv::Size size, const std::string& reason);

/** The frame's image with the overlays `o` asks for. */
cv::Mat drawOmniOverlay(const FrameScan& scan, const Rangefinder& rangefinder, const OverlayOptions& o);

/** The scan from above in the omnicam's frame (forward up, left to the
 * left), `size` px square, a circle every metre to the max range: the
 * omnicam's hits by status, the laser's (cyan) and the truth (white). */
cv::Mat drawScanPlot(const FrameScan& scan, const RangefinderParams& params, int size);

/** Each frame's mean absolute difference over the whole rawlog (score from
 * TunerSession::scoreAll()), `size` px: against the laser (cyan) and the
 * truth (white), frame 0 at the left; a grey line at frame `current`. The
 * vertical scale ends at the 95th percentile of the errors (at least 0.1 m),
 * written in the corner; larger errors are drawn at the top. Not scored yet
 * (no frames in `score`): a line saying how to score. */
cv::Mat drawErrorPlot(const LogScore& score, int current, cv::Size size);
/** The frame a click at column `x` of drawErrorPlot()'s picture `width` px wide stands for. */
int frameAtColumn(int x, int width, int frames);

/** The colours the classifier calls free, most frequent floor colour first,
 * as swatches in a `size` image (one representative colour per bin). */
cv::Mat drawFloorColours(const ColourModel& colours, const FreeSpaceClassifier& classifier, cv::Size size);

}  // namespace omnirange::tuner
