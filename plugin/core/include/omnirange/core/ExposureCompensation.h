#pragma once
// Light that changes between training and use (auto-exposure, white
// balance, clouds, another room's lamps) moves every colour, and a floor
// histogram trained in one light no longer recognises the floor in another:
// the whole ring around the robot turns non-free and every ray reports "too
// close". The floor right around the robot's base is floor nearly always,
// so its colour is a reference: training records its median, and each image
// is brought back to that colour, per channel, before it is classified.

#include <omnirange/core/CameraModel.h>
#include <omnirange/core/PixelClassifier.h>

#include <array>
#include <cstdint>
#include <vector>

#include <opencv2/core/matx.hpp>

namespace cv
{
class Mat;
}

namespace omnirange
{
/** The pixels of a thin ring of floor just outside the robot's base. */
class FloorRing
{
   public:
	/** From the floor distance `inner` [m] (just beyond the base, where
	 * training starts) outwards, `width` [px] wide, one pixel per degree
	 * every `rho_step` px of radius. */
	FloorRing(const OmniCameraModel& camera, double inner, double width = 10.0, double rho_step = 1.0);

	/** The ring's pixels' B, G, R in an 8-bit BGR image of the camera's size. */
	std::vector<cv::Vec3b> colours(const cv::Mat& bgr) const;
	/** Per channel, the median of `colours`. */
	static std::array<double, 3> median(const std::vector<cv::Vec3b>& colours);
	/** median(colours(bgr)). */
	std::array<double, 3> medianColour(const cv::Mat& bgr) const;
	/** How many of the ring's pixels `classifier` calls free floor. */
	int countFree(const cv::Mat& bgr, const PixelClassifier& classifier) const;
	/** The box of the image the ring reads. */
	PixelBox pixelsRead() const;

   private:
	std::vector<std::int32_t> pixels_;  // row * width + col
	int width_, height_;
};

/** Per-channel gains that bring `current` to `reference`, each clamped to
 * [0.5, 2]; all 1 when every gain is within `deadband` of 1 (the ring's
 * median moves by a few per cent as the floor's texture passes under the
 * robot, and a change that small is noise, not light). */
std::array<double, 3> compensatingGains(const std::array<double, 3>& reference, const std::array<double, 3>& current,
										double deadband = 0.0);

/** A classifier that sees each pixel through per-channel gains (the seam of PixelClassifier.h). */
class CompensatedClassifier final : public PixelClassifier
{
   public:
	CompensatedClassifier(const PixelClassifier& base, const std::array<double, 3>& gains);
	void classify(const std::uint8_t* bgr, const std::int32_t* pixels, int count, std::uint8_t* out) const override;

   private:
	const PixelClassifier& base_;
	std::array<std::array<std::uint8_t, 256>, 3> lut_{};
};

}  // namespace omnirange
