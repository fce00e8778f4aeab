#include "omnirange/io/ObservationImage.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>
#include <stdexcept>

namespace omnirange
{
namespace
{
/** Why the bytes of an image file are not a whole JPEG or PNG, or "". A cut
 * file would otherwise decode with grey rows and only a libjpeg warning. */
std::string incompleteImage(const std::vector<unsigned char>& bytes)
{
	const std::string_view b(reinterpret_cast<const char*>(bytes.data()), bytes.size());
	const auto ends_with_within = [&](const std::string& marker, std::size_t tail) {
		const std::size_t from = b.size() > tail ? b.size() - tail : 0;
		return b.find(marker, from) != std::string::npos;
	};
	if (b.size() >= 2 && static_cast<unsigned char>(b[0]) == 0xFF && static_cast<unsigned char>(b[1]) == 0xD8)
		return ends_with_within("\xFF\xD9", 64) ? "" : "truncated: no JPEG end-of-image marker";
	if (b.size() >= 8 && b.substr(1, 3) == "PNG") return ends_with_within("IEND", 16) ? "" : "truncated: no PNG end chunk";
	return "";
}
}  // namespace

cv::Mat decodeImageFile(const std::string& file, const std::string& label)
{
	std::ifstream f(file, std::ios::binary | std::ios::ate);
	std::vector<unsigned char> bytes(f ? static_cast<std::size_t>(f.tellg()) : 0);
	f.seekg(0);
	if (!f || !f.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size())))
		throw std::runtime_error("image '" + file + "' of " + label + " is unreadable");
	if (const std::string why = incompleteImage(bytes); !why.empty())
		throw std::runtime_error("image '" + file + "' of " + label + " is " + why);
	return bytes.empty() ? cv::Mat() : cv::imdecode(bytes, cv::IMREAD_COLOR);
}

cv::Mat decodeImage(const mrpt::obs::CObservationImage& obs)
{
	cv::Mat img;
	if (obs.image.isExternallyStored())
	{
		// Read the file ourselves: CImage's lazy loading shares state between
		// threads and reports a missing file with a stack trace.
		const std::string file = obs.image.getExternalStorageFileAbsolutePath();
		if (std::filesystem::is_regular_file(file)) img = decodeImageFile(file, obs.sensorLabel);
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
