#pragma once
// Omnicam images drawn in the tests: every pixel is painted floor or wall
// colour according to where its ray meets the floor, through the camera
// model (pixels at or above the horizon are wall).

#include <omnirange/core/CameraModel.h>
#include <omnirange/core/ColourHistogram.h>

#include <opencv2/core.hpp>

#include <functional>

namespace omnirange::test
{
inline const cv::Vec3b kFloor{60, 140, 70};  // B, G, R: grass green
inline const cv::Vec3b kWall{40, 60, 150};  // B, G, R: brick red

/** An image of the camera's size; `is_wall(floor point)` decides each pixel. */
inline cv::Mat drawOmni(
	const OmniCameraModel& cam, const std::function<bool(const FloorPoint&)>& is_wall)
{
	const auto& p = cam.params();
	cv::Mat img(p.image_height, p.image_width, CV_8UC3);
	for (int v = 0; v < img.rows; ++v)
		for (int u = 0; u < img.cols; ++u)
		{
			const auto f = cam.floorFromPixel({double(u), double(v)});
			img.at<cv::Vec3b>(v, u) = (!f || is_wall(*f)) ? kWall : kFloor;
		}
	return img;
}

/** Floor inside image radius `rho` [px] (pixel centres within it), wall outside. */
inline cv::Mat drawFloorDisc(const OmniCameraModel& cam, double rho)
{
	const auto& p = cam.params();
	cv::Mat img(p.image_height, p.image_width, CV_8UC3);
	for (int v = 0; v < img.rows; ++v)
		for (int u = 0; u < img.cols; ++u)
			img.at<cv::Vec3b>(v, u) =
				std::hypot(u - p.cx, v - p.cy) <= rho ? kFloor : kWall;
	return img;
}

/** The default camera with the first-order model theta = rho / alpha. */
inline CameraParams firstOrderCamera(double alpha)
{
	CameraParams p;
	p.mirror_model = MirrorModel::FirstOrder;
	p.alpha = alpha;
	return p;
}

/** A histogram that has seen only the floor colour. */
inline ColourHistogram floorHistogram()
{
	ColourHistogram h;
	for (int i = 0; i < 100; ++i) h.addPixel(&kFloor[0]);
	return h;
}

}  // namespace omnirange::test
