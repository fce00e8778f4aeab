#pragma once
// Bird's-eye view of the floor from an omnicam image (paper §III-A1, Nayar's
// eqs. (1)-(3)): what the floor looks like from straight above, robot forward
// up and robot left to the left.

#include <omnirange/core/CameraModel.h>

#include <opencv2/core.hpp>

namespace omnirange
{
class BirdsEyeView
{
   public:
	/** A view `size_px` square, `metres_per_px` per pixel, centred on the
	 * camera's vertical axis. Throws std::invalid_argument on a size < 1 or a
	 * non-positive scale. */
	BirdsEyeView(const OmniCameraModel& camera, int size_px, double metres_per_px);

	/** Remaps one omnicam image (any type cv::remap takes; bilinear). Pixels
	 * that fall outside the omnicam image are black. */
	cv::Mat render(const cv::Mat& omni) const;

	/** Sensor-frame floor point of a view pixel (col, row). */
	FloorPoint floorAt(double col, double row) const;

	int size() const { return size_; }
	double metresPerPixel() const { return mpp_; }

   private:
	int size_;
	double mpp_;
	cv::Mat map_u_, map_v_;  // CV_32F: omnicam pixel of each view pixel
};

}  // namespace omnirange
