#include "omnirange/io/ObservationImage.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <filesystem>
#include <stdexcept>

namespace omnirange
{
cv::Mat decodeImage(const mrpt::obs::CObservationImage& obs)
{
	cv::Mat img;
	if (obs.image.isExternallyStored())
	{
		// Read the file ourselves: CImage's lazy loading shares state between
		// threads and reports a missing file with a stack trace.
		const std::string file = obs.image.getExternalStorageFileAbsolutePath();
		if (std::filesystem::is_regular_file(file)) img = cv::imread(file, cv::IMREAD_COLOR);
		if (img.empty())
			throw std::runtime_error("image '" + file + "' of " + obs.sensorLabel +
									 " is missing or unreadable");
		return img;
	}
	img = obs.image.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	if (img.empty()) throw std::runtime_error("an empty " + obs.sensorLabel + " image");
	if (img.channels() == 1) cv::cvtColor(img, img, cv::COLOR_GRAY2BGR);
	return img.clone();
}

cv::Mat decodeImage(const mrpt::obs::CObservationImage& obs, const CameraParams& cam)
{
	cv::Mat img = decodeImage(obs);
	if (img.cols != cam.image_width || img.rows != cam.image_height)
		throw std::runtime_error(
			"image '" + obs.image.getExternalStorageFile() + "' is " + std::to_string(img.cols) + "x" +
			std::to_string(img.rows) + " but the camera is " + std::to_string(cam.image_width) + "x" +
			std::to_string(cam.image_height));
	return img;
}

}  // namespace omnirange
