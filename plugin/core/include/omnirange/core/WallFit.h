#pragma once
// Thin walls (the paper's future work: the omnicam's walls come out as
// thick, noisy lines). A range's uncertainty follows from the mirror's
// geometry: the boundary is found to about a pixel, and a pixel is 1 cm of
// floor at 1 m but 10 cm at 3.8 m. Neighbouring hits that lie on one
// straight wall are fitted with a line, each weighted by the inverse square
// of its uncertainty, and each ray's range is moved to where its bearing
// meets that line. Runs that are not straight within their uncertainties
// are split where they disagree most (a corner, an object before the wall),
// and pieces too short to fit are left as measured.

#include <omnirange/core/CameraModel.h>
#include <omnirange/core/PolarScanner.h>
#include <omnirange/config/OptionsTable.h>

#include <vector>

namespace omnirange
{
/** The ini keys equal the member names. */
struct WallFitParams
{
	bool wall_fit{true};  ///< on by default: docs/results.md measures it
	int wall_fit_min_rays{6};  ///< [rays] the shortest run fitted with a line (>= 3)
	/** [sigma] a ray is on the line when its range is within this many of
	 * its uncertainties of the line's. */
	double wall_fit_tolerance{3.0};
	/** [px] the boundary's uncertainty in the image, which the mirror turns
	 * into each ray's range uncertainty. */
	double boundary_sigma{0.5};

	static const OptionsTable<WallFitParams>& table();
	void validate() const;  ///< throws std::invalid_argument on an impossible value
};

/** [m] The range uncertainty of a boundary found at image radius `rho`:
 * `boundary_sigma` pixels' worth of floor distance there. */
double rangeSigma(const OmniCameraModel& camera, double rho, double boundary_sigma);

/** Moves the hit rays of `rays` (a whole scan, in bearing order, wrapping
 * round) that lie on straight walls onto their fitted lines, unless that
 * would take a range out of [min_range, max_range]; returns how many it
 * moved. Nothing happens when p.wall_fit is false. */
int fitWalls(std::vector<Ray>& rays, const OmniCameraModel& camera, const WallFitParams& p, double min_range,
			 double max_range);

}  // namespace omnirange
