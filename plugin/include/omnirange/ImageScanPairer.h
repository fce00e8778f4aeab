#pragma once
// Pairs each omnicam image with the laser scan taken with it while a rawlog
// streams by (training and calibration both need such pairs).

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>

#include <set>
#include <string>

namespace omnirange
{
class ImageScanPairer
{
   public:
	/** An image and a scan pair up when their timestamps differ by at most max_dt [s]. */
	ImageScanPairer(std::string omni_label, std::string laser_label, double max_dt);

	/** Feeds the next object; true when it completes a pair, then held by image() and scan(). */
	bool add(const mrpt::serialization::CSerializable::Ptr& obj);
	const mrpt::obs::CObservationImage::Ptr& image() const { return image_; }
	const mrpt::obs::CObservation2DRangeScan::Ptr& scan() const { return scan_; }

	/** The error for a rawlog in which no pair was found, naming the labels it has. */
	std::string noPairError(const std::string& rawlog) const;

   private:
	std::string omni_, laser_;
	double max_dt_;
	mrpt::obs::CObservationImage::Ptr image_;
	mrpt::obs::CObservation2DRangeScan::Ptr scan_;
	bool paired_{false};
	std::set<std::string> labels_;
};

}  // namespace omnirange
