#include "omnirange/train/HistogramTrainer.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace omnirange
{
const OptionsTable<TrainingParams>& TrainingParams::table()
{
	using T = TrainingParams;
	static const auto t =
		OptionsTable<T>()
			.add("bins", "bins", "histogram bins per colour channel", [](T& t) -> auto& { return t.bins; })
			.within(Range::closed(1, 256))
			.addEnum("colour_space", "the histogram's colour space (CHROMA: rg chromaticity and log brightness)",
					 [](T& t) -> auto& { return t.space; }, colourSpaceFromString,
					 {ColourSpace::RGB, ColourSpace::HSV, ColourSpace::Chroma})
			// Farther than the laser sees is no margin; a huge one only costs time (each hit walks it).
			.add("laser_margin", "m", "distance kept clear of every laser hit (mixed pixels)",
				 [](T& t) -> auto& { return t.laser_margin; })
			.within(Range::closed(0, 5))
			.add("obstacle_band", "m",
				 "how far beyond each laser hit the obstacle's colours are counted (the two-class model); 0: the "
				 "floor only",
				 [](T& t) -> auto& { return t.obstacle_band; })
			.within(Range::closed(0, 5))
			.add("light_change", "-",
				 "also count every floor pixel as seen in light this much dimmer and brighter (gains 1 - a, 1 + a); "
				 "0: as seen",
				 [](T& t) -> auto& { return t.light_change; })
			.within(Range::openHigh(0, 1));
	return t;
}

cv::Mat withGain(const cv::Mat& bgr, double gain)
{
	if (gain == 1.0) return bgr;
	cv::Mat m;
	bgr.convertTo(m, -1, gain);  // saturates at 255, as a sensor does
	return m;
}

namespace
{
/** The image as seen, and (when a > 0) as seen with gains 1 - a and 1 + a. */
std::vector<cv::Mat> asInOtherLight(const cv::Mat& bgr, double a)
{
	std::vector<cv::Mat> seen{bgr};
	if (a > 0)
		for (const double gain : {1.0 - a, 1.0 + a}) seen.push_back(withGain(bgr, gain));
	return seen;
}
}  // namespace

HistogramTrainer::HistogramTrainer(const OmniCameraModel& camera, const mrpt::poses::CPose3D& camera_pose,
								   double base_range, double view_range, const TrainingParams& p)
	: camera_pose_(camera_pose),
	  view_range_(view_range),
	  p_(p),
	  view_(camera, 2 * static_cast<int>(std::ceil(view_range / p.resolution)) + 1, p.resolution),
	  hist_(p.space, p.bins),
	  obstacles_(p.space, p.bins),
	  ring_(camera, base_range)
{
	if (!(view_range > 0) || !(p.resolution > 0) || !(p.laser_margin >= 0) || !(base_range >= 0) ||
		!(p.obstacle_band >= 0))
		throw std::invalid_argument("training: view range and resolution must be > 0, margins >= 0");
	if (!(p.light_change >= 0 && p.light_change < 1))
		throw std::invalid_argument("training: light_change must be within [0, 1)");
	// Pixels between the base and view_range: a ring around the centre.
	const int n = view_.size();
	base_mask_ = cv::Mat::zeros(n, n, CV_8UC1);
	const cv::Point c(n / 2, n / 2);
	cv::circle(base_mask_, c, static_cast<int>(view_range / p.resolution), cv::Scalar(255), cv::FILLED);
	cv::circle(base_mask_, c, static_cast<int>(std::ceil(base_range / p.resolution)), cv::Scalar(0), cv::FILLED);
}

cv::Mat HistogramTrainer::laserFreeMask(const mrpt::obs::CObservation2DRangeScan& laser, cv::Mat& obstacle) const
{
	// The laser's pose in the camera's frame: both poses are on the robot.
	const mrpt::poses::CPose3D rel = laser.sensorPose - camera_pose_;
	const int n = view_.size();
	const double c = 0.5 * (n - 1), mpp = view_.metresPerPixel();
	// Sensor frame (x forward, y left) -> view pixel (forward up, left left).
	const auto toPx = [&](double x, double y) {
		return cv::Point(static_cast<int>(std::lround(c - y / mpp)), static_cast<int>(std::lround(c - x / mpp)));
	};
	const double reach = 2.0 * view_range_;  // invalid rays: free beyond the view
	std::vector<cv::Point> poly{toPx(rel.x(), rel.y())};
	std::vector<cv::Point> hits;
	obstacle = cv::Mat::zeros(n, n, CV_8UC1);
	for (std::size_t i = 0; i < laser.getScanSize(); ++i)
	{
		const bool valid = laser.getScanRangeValidity(i);
		const double r = valid ? laser.getScanRange(i) : reach;
		const double a = laser.getScanAngle(i);
		mrpt::math::TPoint3D local(r * std::cos(a), r * std::sin(a), 0), inCam;
		rel.composePoint(local, inCam);
		poly.push_back(toPx(inCam.x, inCam.y));
		if (!valid) continue;
		hits.push_back(poly.back());
		// What stands at the hit continues away from the camera in the
		// bird's-eye view (a wall's face projects onto the floor beyond its foot).
		const double len = std::hypot(inCam.x, inCam.y);
		if (p_.obstacle_band <= 0 || len <= 0 || len > view_range_) continue;
		const double ux = inCam.x / len, uy = inCam.y / len;
		const double a0 = p_.laser_margin, a1 = p_.laser_margin + p_.obstacle_band;
		cv::line(obstacle, toPx(inCam.x + ux * a0, inCam.y + uy * a0), toPx(inCam.x + ux * a1, inCam.y + uy * a1),
				 cv::Scalar(255), 2);
	}
	cv::Mat mask = cv::Mat::zeros(n, n, CV_8UC1);
	cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{poly}, cv::Scalar(255));
	// Keep clear of every hit: its neighbourhood mixes floor and obstacle.
	const int margin = static_cast<int>(std::ceil(p_.laser_margin / mpp));
	if (margin > 0)
		for (const auto& h : hits) cv::circle(mask, h, margin, cv::Scalar(0), cv::FILLED);
	return mask;
}

cv::Mat HistogramTrainer::nearDisc(const mrpt::obs::CObservation2DRangeScan& laser) const
{
	const mrpt::poses::CPose3D rel = laser.sensorPose - camera_pose_;
	double nearest = view_range_;
	for (std::size_t i = 0; i < laser.getScanSize(); ++i)
	{
		if (!laser.getScanRangeValidity(i)) continue;
		const double r = laser.getScanRange(i), a = laser.getScanAngle(i);
		mrpt::math::TPoint3D inCam;
		rel.composePoint(mrpt::math::TPoint3D(r * std::cos(a), r * std::sin(a), 0), inCam);
		nearest = std::min(nearest, std::hypot(inCam.x, inCam.y));
	}
	const int n = view_.size();
	cv::Mat disc = cv::Mat::zeros(n, n, CV_8UC1);
	const double radius = (nearest - p_.laser_margin) / view_.metresPerPixel();
	if (radius > 0) cv::circle(disc, cv::Point(n / 2, n / 2), static_cast<int>(radius), cv::Scalar(255), cv::FILLED);
	return disc;
}

TrainingFrame HistogramTrainer::add(const cv::Mat& omni, const mrpt::obs::CObservation2DRangeScan& laser)
{
	TrainingFrame f;
	f.birds_eye = view_.render(omni);  // (a)
	cv::Mat obstacle;
	f.laser_free = laserFreeMask(laser, obstacle);  // (b)
	cv::Mat use;
	cv::bitwise_and(p_.near_disc_only ? nearDisc(laser) : f.laser_free, base_mask_, use);
	f.fused = cv::Mat::zeros(f.birds_eye.size(), CV_8UC3);  // (c)
	f.birds_eye.copyTo(f.fused, use);
	const std::vector<cv::Mat> lights = asInOtherLight(f.birds_eye, p_.light_change);
	for (const cv::Mat& seen : lights) hist_.addImage(seen, use);
	f.pixels = static_cast<std::size_t>(cv::countNonZero(use));
	// Obstacle pixels: never where the laser saw floor, nor on the base.
	cv::Mat not_free;
	cv::bitwise_not(f.laser_free, not_free);
	cv::bitwise_and(obstacle, not_free, obstacle);
	cv::bitwise_and(obstacle, base_mask_, obstacle);
	for (const cv::Mat& seen : lights) obstacles_.addImage(seen, obstacle);
	f.obstacle_pixels = static_cast<std::size_t>(cv::countNonZero(obstacle));
	const auto ring = ring_.medianColour(omni);
	for (int c = 0; c < 3; ++c) ring_sum_[c] += ring[c];
	++frames_;
	return f;
}

void HistogramTrainer::merge(const HistogramTrainer& other)
{
	hist_.merge(other.hist_);
	obstacles_.merge(other.obstacles_);
	for (int c = 0; c < 3; ++c) ring_sum_[c] += other.ring_sum_[c];
	frames_ += other.frames_;
}

ColourModel HistogramTrainer::model() const
{
	ColourModel m(hist_, obstacles_);
	if (frames_ > 0)
		for (int c = 0; c < 3; ++c) m.reference[c] = ring_sum_[c] / frames_;
	return m;
}

}  // namespace omnirange
