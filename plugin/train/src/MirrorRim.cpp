#include "omnirange/train/MirrorRim.h"
#include "omnirange/io/ObservationImage.h"
#include "omnirange/config/OptionsTable.h"
#include "omnirange/config/Temporaries.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <stdexcept>

namespace omnirange
{
MirrorRim detectMirrorRim(const std::vector<std::string>& images)
{
	requireNamedOnce(images, "image");  // one photograph given twice would count as two
	cv::Mat brightest;
	for (const auto& file : images)
	{
		temporaries::setActivity("reading image '" + file + "'");
		const cv::Mat gray = decodeImageFile(file, "", cv::IMREAD_GRAYSCALE);
		if (brightest.empty()) brightest = gray.clone();
		else if (gray.size() != brightest.size())
			throw std::runtime_error("image '" + file + "' is " + sizeText(gray.size()) + ", the first image " +
									 sizeText(brightest.size()) + ": one of them is not of this camera");
		else cv::max(brightest, gray, brightest);
	}
	if (brightest.empty()) throw std::runtime_error("no image to find the mirror in");
	// Which images: the user's own names, in every message below.
	const std::string named = images.size() == 1 ? "'" + images[0] + "'"
												 : "'" + images[0] + "' and " + std::to_string(images.size() - 1) + " more";
	cv::Mat mask;
	const double otsu = cv::threshold(brightest, mask, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
	cv::threshold(brightest, mask, 0.6 * otsu, 255, cv::THRESH_BINARY);
	std::vector<std::vector<cv::Point>> contours;
	cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
	const auto largest = std::max_element(contours.begin(), contours.end(), [](const auto& a, const auto& b) {
		return cv::contourArea(a) < cv::contourArea(b);
	});
	if (largest == contours.end() || largest->size() < 5 || cv::contourArea(*largest) < 0.01 * brightest.total())
		throw std::runtime_error("no bright mirror disc found in " + named);
	std::vector<cv::Point> hull;
	cv::convexHull(*largest, hull);
	if (hull.size() < 5)
		throw std::runtime_error("no mirror disc found in " + named + ": the bright region has no round edge");
	const cv::RotatedRect e = cv::fitEllipse(hull);
	const double a = std::max(e.size.width, e.size.height) / 2, b = std::min(e.size.width, e.size.height) / 2;
	return {e.center.x, e.center.y, (a + b) / 2, 1.0 - b / a, brightest.cols, brightest.rows};
}

}  // namespace omnirange
