#include "omnirange/train/MirrorRim.h"
#include "omnirange/io/ObservationImage.h"
#include "omnirange/config/OptionsTable.h"
#include "omnirange/config/Activity.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace omnirange
{
namespace
{
/** The ellipse of the largest bright region of `gray` (the mirror's disc), or nullopt. */
std::optional<cv::RotatedRect> discIn(const cv::Mat& gray)
{
	cv::Mat mask;
	const double otsu = cv::threshold(gray, mask, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
	cv::threshold(gray, mask, 0.6 * otsu, 255, cv::THRESH_BINARY);
	std::vector<std::vector<cv::Point>> contours;
	cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
	const auto largest = std::max_element(contours.begin(), contours.end(), [](const auto& a, const auto& b) {
		return cv::contourArea(a) < cv::contourArea(b);
	});
	if (largest == contours.end() || largest->size() < 5 || cv::contourArea(*largest) < 0.01 * gray.total())
		return std::nullopt;
	std::vector<cv::Point> hull;
	cv::convexHull(*largest, hull);
	if (hull.size() < 5) return std::nullopt;
	return cv::fitEllipse(hull);
}
}  // namespace

MirrorRim detectMirrorRim(const std::vector<std::string>& images)
{
	requireNamedOnce(images, "image");  // one photograph given twice would count as two
	cv::Mat brightest;
	std::vector<cv::Point2f> centres;  // each image's own disc, where one is found in it alone
	for (const auto& file : images)
	{
		activity::set("reading image '" + file + "'");
		const cv::Mat gray = decodeImageFile(file, "", cv::IMREAD_GRAYSCALE);
		if (brightest.empty()) brightest = gray.clone();
		else if (gray.size() != brightest.size())
			throw std::runtime_error("image '" + file + "' is " + sizeText(gray.size()) + ", the first image " +
									 sizeText(brightest.size()) + ": one of them is not of this camera");
		else cv::max(brightest, gray, brightest);
		if (const auto own = discIn(gray)) centres.push_back(own->center);
	}
	if (brightest.empty()) throw std::runtime_error("no image to find the mirror in");
	// Which images: the user's own names, in every message below.
	const std::string named = images.size() == 1 ? "'" + images[0] + "'"
												 : "'" + images[0] + "' and " + std::to_string(images.size() - 1) + " more";
	// Their brightest pixels together: parts of the rim dark in one image are lit in another.
	const auto e = discIn(brightest);
	if (!e) throw std::runtime_error("no bright mirror disc found in " + named);
	const double a = std::max(e->size.width, e->size.height) / 2, b = std::min(e->size.width, e->size.height) / 2;
	MirrorRim rim{e->center.x, e->center.y, (a + b) / 2, 1.0 - b / a, brightest.cols, brightest.rows};
	for (const auto& c : centres)
		rim.centre_spread = std::max(rim.centre_spread, std::hypot(c.x - rim.cx, c.y - rim.cy));
	return rim;
}

}  // namespace omnirange
