#include "omnirange/core/ExposureCompensation.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace omnirange
{
FloorRing::FloorRing(const OmniCameraModel& camera, double inner, double width, double rho_step)
	: width_(camera.params().image_width), height_(camera.params().image_height)
{
	if (!(rho_step > 0)) throw std::invalid_argument("FloorRing: rho_step must be > 0");
	const double from = camera.rhoFromDistance(inner);
	for (double rho = from; rho < from + width; rho += rho_step)
		for (int deg = 0; deg < 360; ++deg)
		{
			const Pixel p = camera.pixelFromPolar(deg * 3.14159265358979323846 / 180.0, rho);
			const long u = std::lround(p.u), v = std::lround(p.v);
			if (u >= 0 && v >= 0 && u < width_ && v < height_) pixels_.push_back(static_cast<std::int32_t>(v * width_ + u));
		}
	if (pixels_.empty()) throw std::invalid_argument("the floor ring around the base lies outside the image");
}

PixelBox FloorRing::pixelsRead() const
{
	PixelBox box;
	box.add(pixels_, width_);
	return box;
}

std::vector<cv::Vec3b> FloorRing::colours(const cv::Mat& bgr) const
{
	if (bgr.type() != CV_8UC3 || bgr.cols != width_ || bgr.rows != height_)
		throw std::invalid_argument("FloorRing: the image must be an 8-bit BGR image of the camera's size");
	std::vector<cv::Vec3b> out;
	out.reserve(pixels_.size());
	for (const std::int32_t p : pixels_) out.push_back(bgr.at<cv::Vec3b>(p / width_, p % width_));
	return out;
}

namespace
{
/** Per channel, the value at index n / 2 of the sorted values (the upper
 * median), from counts of each of the 256 values: no sort, no copy. */
std::array<double, 3> medianOfCounts(const std::array<std::array<int, 256>, 3>& counts, std::size_t n)
{
	std::array<double, 3> out{};
	for (int c = 0; c < 3; ++c)
	{
		std::size_t below = 0;
		int v = 0;
		while (below + static_cast<std::size_t>(counts[c][v]) <= n / 2) below += static_cast<std::size_t>(counts[c][v++]);
		out[c] = v;
	}
	return out;
}
}  // namespace

std::array<double, 3> FloorRing::median(const std::vector<cv::Vec3b>& colours)
{
	if (colours.empty()) return {};
	std::array<std::array<int, 256>, 3> counts{};
	for (const cv::Vec3b& p : colours)
		for (int c = 0; c < 3; ++c) ++counts[c][p[c]];
	return medianOfCounts(counts, colours.size());
}

std::array<double, 3> FloorRing::medianColour(const cv::Mat& bgr) const
{
	if (!bgr.isContinuous()) return median(colours(bgr));
	if (bgr.type() != CV_8UC3 || bgr.cols != width_ || bgr.rows != height_)
		throw std::invalid_argument("FloorRing: the image must be an 8-bit BGR image of the camera's size");
	// Once a frame, on the hot path: counted straight from the image.
	std::array<std::array<int, 256>, 3> counts{};
	const auto* image = bgr.ptr<cv::Vec3b>();
	for (const std::int32_t p : pixels_)
		for (int c = 0; c < 3; ++c) ++counts[c][image[p][c]];
	return medianOfCounts(counts, pixels_.size());
}

int FloorRing::countFree(const cv::Mat& bgr, const PixelClassifier& classifier) const
{
	if (bgr.type() != CV_8UC3 || bgr.cols != width_ || bgr.rows != height_)
		throw std::invalid_argument("FloorRing: the image must be an 8-bit BGR image of the camera's size");
	const cv::Mat image = bgr.isContinuous() ? bgr : bgr.clone();  // pixel indices are row * width + col
	// In runs, so a frame's check allocates nothing.
	std::array<std::uint8_t, 256> free;
	const int n = static_cast<int>(pixels_.size());
	int count = 0;
	for (int from = 0; from < n; from += static_cast<int>(free.size()))
	{
		const int run = std::min(static_cast<int>(free.size()), n - from);
		classifier.classify(image.ptr<std::uint8_t>(), pixels_.data() + from, run, free.data());
		count += static_cast<int>(std::count_if(free.begin(), free.begin() + run, [](std::uint8_t f) { return f != 0; }));
	}
	return count;
}

std::array<double, 3> compensatingGains(const std::array<double, 3>& reference, const std::array<double, 3>& current,
										double deadband)
{
	std::array<double, 3> g{};
	bool small = true;
	for (int c = 0; c < 3; ++c)
	{
		g[c] = std::clamp(std::max(1.0, reference[c]) / std::max(1.0, current[c]), 0.5, 2.0);
		// A median moves in whole grey levels: one level is never a change
		// of light, however dark the channel.
		small = small && (std::abs(g[c] - 1.0) < deadband || std::abs(reference[c] - current[c]) <= 1.0);
	}
	if (small) g = {1.0, 1.0, 1.0};
	return g;
}

CompensatedClassifier::CompensatedClassifier(const PixelClassifier& base, const std::array<double, 3>& gains)
	: base_(base)
{
	for (int c = 0; c < 3; ++c)
		for (int x = 0; x < 256; ++x)
			lut_[c][x] = static_cast<std::uint8_t>(std::min(255L, std::lround(x * gains[c])));
}

void CompensatedClassifier::classify(const std::uint8_t* bgr, const std::int32_t* pixels, int count,
									 std::uint8_t* out) const
{
	// Through the base one pixel at a time, from a small buffer of compensated colours.
	constexpr int kRun = 16;
	static constexpr std::int32_t kIndex[kRun] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
	std::uint8_t buf[3 * kRun];
	for (int from = 0; from < count; from += kRun)
	{
		const int n = std::min(kRun, count - from);
		for (int k = 0; k < n; ++k)
		{
			const std::uint8_t* p = bgr + 3 * static_cast<std::size_t>(pixels[from + k]);
			for (int c = 0; c < 3; ++c) buf[3 * k + c] = lut_[c][p[c]];
		}
		base_.classify(buf, kIndex, n, out + from);
	}
}

}  // namespace omnirange
