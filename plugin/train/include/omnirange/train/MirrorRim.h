#pragma once
// The mirror's centre and rim radius found in ordinary images, without a
// board or a laser: a catadioptric image is a bright disc (the mirror) on a
// dark surround. Over a few images, each pixel's brightest value fills the
// disc; the disc is the largest region brighter than 0.6 of Otsu's threshold
// (darker parts of the rim would cut into a region at Otsu's own); its convex
// hull, fitted with an ellipse, gives the centre and the radius. A first
// guess of cx, cy for the ini; the checkerboard calibration measures the
// principal point itself.

#include <string>
#include <vector>

namespace omnirange
{
struct MirrorRim
{
	double cx{0}, cy{0};  ///< [px] the disc's centre
	double radius{0};  ///< [px] mean of the fitted ellipse's half axes
	double ellipticity{0};  ///< [-] 1 - minor / major axis: large means a tilted camera or a wrong fit
	int image_width{0}, image_height{0};  ///< [px] of the images it was found in
	/** [px] the farthest any one image's own disc centre is from (cx, cy):
	 * large when the camera or the mirror moved between the images (0 for one image). */
	double centre_spread{0};
};

/** Throws std::runtime_error naming the file if an image cannot be read or
 * has another size than the first, or if no disc is found. */
MirrorRim detectMirrorRim(const std::vector<std::string>& images);

}  // namespace omnirange
