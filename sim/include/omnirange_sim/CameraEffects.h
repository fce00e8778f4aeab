#pragma once
// What a real camera does to the picture before the rangefinder sees it,
// each switchable in the robot ini's [omnicam] section (docs/worlds.md):
// vignetting and optical blur (the lens), exposure and white-balance drift
// along the route (auto-exposure, changing light), and a Bayer colour
// filter with demosaicing (a single-chip sensor). Sensor noise and JPEG's
// 4:2:0 chroma compression are applied by the renderer and the writer.

#include <opencv2/core.hpp>

namespace omnirange::sim
{
struct CameraEffectsParams
{
	double blur_sigma{0};  ///< [px] Gaussian blur of the optics (0: none)
	double vignetting{0};  ///< [-] darkening at the mirror's rim: 1 - v (r / r_rim)^2 (0: none)
	double exposure_drift{0};  ///< [-] amplitude of the gain's swing along the route (0: none)
	double white_balance_drift{0};  ///< [-] amplitude of red against blue gain swings (0: none)
	double drift_period{200};  ///< [frames] period of both swings
	bool bayer{false};  ///< RGGB mosaic, then demosaiced as a camera would
};

/** Vignetting (around (cx, cy), reaching `vignetting` at radius rim_rho),
 * then blur: what the optics do. */
void applyOptics(cv::Mat& bgr, const CameraEffectsParams& p, double cx, double cy, double rim_rho);

/** Exposure and white balance of frame `frame`: gains that swing with the route. */
void applyExposure(cv::Mat& bgr, const CameraEffectsParams& p, int frame);

/** Keeps one colour per pixel (RGGB) and interpolates the others back. */
void applyBayer(cv::Mat& bgr);

}  // namespace omnirange::sim
