#include "omnirange/ImageScanPairer.h"

#include <cmath>

namespace omnirange
{
ImageScanPairer::ImageScanPairer(std::string omni_label, std::string laser_label, double max_dt)
	: omni_(std::move(omni_label)), laser_(std::move(laser_label)), max_dt_(max_dt)
{
}

bool ImageScanPairer::add(const mrpt::serialization::CSerializable::Ptr& obj)
{
	auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj);
	if (!obs) return false;
	labels_.insert(obs->sensorLabel);
	if (paired_) image_.reset(), scan_.reset(), paired_ = false;  // each observation pairs once
	if (auto im = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obs); im && im->sensorLabel == omni_)
		image_ = im;
	else if (auto sc = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs); sc && sc->sensorLabel == laser_)
		scan_ = sc;
	else
		return false;
	paired_ = image_ && scan_ && std::abs(mrpt::system::timeDifference(image_->timestamp, scan_->timestamp)) <= max_dt_;
	return paired_;
}

std::string ImageScanPairer::noPairError(const std::string& rawlog) const
{
	std::string all;
	for (const auto& l : labels_) all += (all.empty() ? "" : ", ") + l;
	return "no " + omni_ + " image had a " + laser_ + " scan within " + std::to_string(max_dt_) + " s in '" + rawlog +
		"' (labels found: " + (all.empty() ? "none" : all) + "); training needs both";
}

}  // namespace omnirange
