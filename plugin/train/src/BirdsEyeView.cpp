#include "omnirange/train/BirdsEyeView.h"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <stdexcept>

namespace omnirange
{
BirdsEyeView::BirdsEyeView(
	const OmniCameraModel& cam, int size_px, double metres_per_px)
	: size_(size_px), mpp_(metres_per_px)
{
	if (size_px < 1) throw std::invalid_argument("bird's-eye view size must be >= 1 px");
	if (!(metres_per_px > 0))
		throw std::invalid_argument("bird's-eye view scale must be > 0 m/px");
	map_u_.create(size_, size_, CV_32F);
	map_v_.create(size_, size_, CV_32F);
	// z: the viewpoint's height over the projection plane, in view pixels.
	const double z = cam.params().h / mpp_;
	for (int row = 0; row < size_; ++row)
		for (int col = 0; col < size_; ++col)
		{
			const FloorPoint f = floorAt(col, row);
			const double xb = f.x / mpp_, yb = f.y / mpp_;
			const double theta = std::acos(z / std::sqrt(xb * xb + yb * yb + z * z));  // eq. (1)
			const double phi = std::atan2(yb, xb);  // eq. (2), a bearing
			// eqs. (2)-(3): r sin(theta) = R tan(theta/2) = rho for the
			// paraboloid; rhoFromTheta() also covers the first-order model.
			const Pixel p = cam.pixelFromPolar(phi, cam.rhoFromTheta(theta));
			map_u_.at<float>(row, col) = static_cast<float>(p.u);
			map_v_.at<float>(row, col) = static_cast<float>(p.v);
		}
}

FloorPoint BirdsEyeView::floorAt(double col, double row) const
{
	const double c = 0.5 * (size_ - 1);
	return {(c - row) * mpp_, (c - col) * mpp_};
}

cv::Mat BirdsEyeView::render(const cv::Mat& omni) const
{
	cv::Mat out;
	cv::remap(
		omni, out, map_u_, map_v_, cv::INTER_LINEAR, cv::BORDER_CONSTANT,
		cv::Scalar::all(0));
	return out;
}

}  // namespace omnirange
