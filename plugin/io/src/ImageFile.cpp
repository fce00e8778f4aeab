#include "omnirange/io/ImageFile.h"

#include <opencv2/imgcodecs.hpp>

#include <stdexcept>
#include <vector>

namespace omnirange
{
std::string encodedImage(const std::string& path, const cv::Mat& image)
{
	const auto dot = path.rfind('.');
	std::vector<uchar> buf;
	if (dot == std::string::npos || !cv::imencode(path.substr(dot), image, buf))
		throw std::runtime_error("cannot encode image '" + path + "'");
	return std::string(buf.begin(), buf.end());
}

void writeImageAtomically(const std::string& path, const cv::Mat& image)
{
	writeFileAtomically(path, encodedImage(path, image));
}

void stageImage(OutputSet& set, const std::string& path, const cv::Mat& image)
{
	set.write({path, OutputKind::Image}, encodedImage(path, image));
}
}  // namespace omnirange
