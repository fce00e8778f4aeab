#include "omnirange/OmniRangefinderSensor.h"

#include "omnirange/ObservationImage.h"

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/obs/CObservationImage.h>

#include <stdexcept>

namespace omnirange
{
IMPLEMENTS_GENERIC_SENSOR(COmniRangefinderSensor, omnirange)

COmniRangefinderSensor::COmniRangefinderSensor() = default;
COmniRangefinderSensor::~COmniRangefinderSensor() = default;

void COmniRangefinderSensor::loadConfig_sensorSpecific(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	// The section also holds CGenericSensor's own keys and ours.
	params_.loadFromConfig(
		cfg, section,
		{"driver", "process_rate", "max_queue_len", "grab_decimation", "sensorLabel", "camera_section",
		 "histogram_file"});
	histogram_file_ = cfg.read_string(section, "histogram_file", "", true);
	const std::string cam = cfg.read_string(section, "camera_section", "", true);
	if (!cfg.sectionExists(cam))
		throw std::invalid_argument("[" + section + "] camera_section: no section [" + cam + "]");
	camera_ = std::make_unique<mrpt::hwdrivers::CCameraSensor>();
	camera_->loadConfig(cfg, cam);
}

void COmniRangefinderSensor::initialize()
{
	rangefinder_ = std::make_unique<Rangefinder>(params_, ColourHistogram::load(histogram_file_));
	camera_->initialize();
}

void COmniRangefinderSensor::setPathForExternalImages(const std::string& directory)
{
	if (camera_) camera_->setPathForExternalImages(directory);
}

void COmniRangefinderSensor::doProcess()
{
	if (!rangefinder_) throw std::logic_error("COmniRangefinderSensor: doProcess() before initialize()");
	const auto obs = camera_->getNextFrame();
	const auto img = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obs);
	if (!img) return;  // no frame now (or a camera type without a single image)
	const cv::Mat bgr = decodeImage(*img);
	// Keep the image inside the observation: a replayed frame's external file
	// is not beside the rawlog being grabbed.
	img->image = mrpt::img::CImage(bgr, mrpt::img::DEEP_COPY);
	auto scan = rangefinder_->toObservation(rangefinder_->process(bgr), img->timestamp);
	appendObservations({img, scan});
	++frames_;
}

}  // namespace omnirange
